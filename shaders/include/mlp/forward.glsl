// The forward pass of one sample, layer by layer from MLP_LAYER_TABLE (literal widths, so every
// loop has a constant trip count the compiler can unroll). The including shader declares
// `float u[MLP_UNITS]` (inputs in u[0..MLP_IN), filled by it; outputs end up in
// u[MLP_OUT_UNIT..]) and defines MLP_W(p), parameter p of the flat layout (nn/mlp_spec.h). It
// may define MLP_ON_UNIT(k, a) to see each unit as it is computed.
#include "mlp/activation.glsl"

#ifndef MLP_ON_UNIT
#define MLP_ON_UNIT(k, a)
#endif

#define MLP_OUT_UNIT (MLP_UNITS - MLP_OUT)

#define MLP_FORWARD_LAYER(L, IN, OUT, WOFF, BOFF, UIN, UOUT)          \
  for (int j = 0; j < OUT; ++j) {                                     \
    float z = MLP_W(BOFF + j);                                        \
    for (int i = 0; i < IN; ++i) z += MLP_W(WOFF + j * IN + i) * u[UIN + i]; \
    float a = mlp_activate(MLP_LAYER_ACT(L), z);                      \
    u[UOUT + j] = a;                                                  \
    MLP_ON_UNIT(UOUT + j, a)                                          \
  }

#define MLP_FORWARD() MLP_LAYER_TABLE(MLP_FORWARD_LAYER)

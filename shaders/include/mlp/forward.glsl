// The forward pass of one sample on the padded vec4 layout (runtime/nn/mlp_shader.h), run by run
// from MLP_RUN_TABLE. The including shader defines
//   MLP_P4(k)              parameter vec4 k of the network,
//   MLP_UNIT(b, u0, k)     lvalue: vec4 k of this sample's width block b (0 = inputs .. MLP_LAYERS
//                          = outputs), which starts at unit vec4 u0 when the blocks are laid end
//                          to end (inputs filled by the shader; the outputs' padding ends 0),
//   MLP_ROLLED(n)          the bound of a loop that should stay a loop: `((n) + u_zero)` (code
//                          size, compile time), or `(n)` to let the compiler unroll it;
//   MLP_KEEP_GRAD(u, g)    optional (training): store f'(z) of output unit vec4 u (its index
//                          among the unit vec4s) where the backward pass finds it; called only
//                          for layers whose derivative does not follow from their output.
// Rows past the layer's width (the padding of its last output vec4) repeat its last row and are
// masked to 0, so every row loop runs over whole vec4s.
#include "mlp/activation.glsl"

#ifndef MLP_KEEP_GRAD
#define MLP_KEEP_GRAD(u, g)
#endif

#define MLP_FORWARD_RUN(L0, COUNT, IN, OUT, IN4, OUT4, WQ0, UI0, QN)                             \
  for (int k_ = 0; k_ < MLP_ROLLED(COUNT); ++k_) {                                               \
    const int l_ = L0 + k_, wq_ = WQ0 + k_ * (OUT * IN4 + OUT4), bq_ = wq_ + OUT * IN4;          \
    const int ui_ = UI0 + k_ * IN4, uo_ = ui_ + IN4;                                             \
    vec4 ain[IN4];                                                                               \
    for (int q = 0; q < QN; ++q) ain[q] = MLP_UNIT(l_, ui_, q);                                 \
    for (int jq = 0; jq < MLP_ROLLED(OUT4); ++jq) {                                              \
      vec4 z = MLP_P4(bq_ + jq);                                                                 \
      for (int c = 0; c < 4; ++c) {                                                              \
        int j = min(4 * jq + c, OUT - 1);                                                        \
        float s = 0.0;                                                                           \
        for (int q = 0; q < QN; ++q) s += dot(MLP_P4(wq_ + j * IN4 + q), ain[q]);                \
        z[c] += s;                                                                               \
      }                                                                                          \
      MLP_UNIT(l_ + 1, uo_, jq) = mix(vec4(0.0), MLP_LAYER_ACTIVATE(L0, z), mlp_live(jq, OUT));          \
      if (MLP_LAYER_KEEPS_GRAD(L0))                                                              \
        MLP_KEEP_GRAD(uo_ + jq, mix(vec4(0.0), MLP_LAYER_GRAD_Z(L0, z), mlp_live(jq, OUT)));     \
    }                                                                                            \
  }

#define MLP_FORWARD() MLP_RUN_TABLE(MLP_FORWARD_RUN)

// The network's activations, from the registry of runtime/nn/activation.h: the host passes
// their GLSL as in-memory includes (mlp/act_hidden.glsl, mlp/act_output.glsl; empty when the
// output layer's is the hidden one) and names them in defines (runtime/nn/mlp_shader.cpp):
//   MLP_ACT_F(z), MLP_ACT_GRAD_Z(z)   f and f' of the pre-activation z, hidden layers;
//   MLP_ACT_FROM_OUTPUT               1 when f' follows from the output a = f(z), then
//   MLP_ACT_GRAD_A(a)                 is that derivative (the backward pass stores nothing);
//   MLP_OUT_ACT_...                   the same for the output layer.
// tanh as the [13/6] rational function of runtime/nn/fast_tanh.h (the cpu backend's): no exp,
// no cancellation near 0, |error| <= 1e-6; comparisons through mix() let NaN pass.
vec4 mlp_tanh(vec4 x) {
  const vec4 c = vec4(7.90531110763549805);
  x = mix(x, c, greaterThan(x, c));
  x = mix(x, -c, lessThan(x, -c));
  vec4 x2 = x * x;
  vec4 p = x2 * -2.76076847742355e-16 + 2.00018790482477e-13;
  p = x2 * p + -8.60467152213735e-11;
  p = x2 * p + 5.12229709037114e-08;
  p = x2 * p + 1.48572235717979e-05;
  p = x2 * p + 6.37261928875436e-04;
  p = x2 * p + 4.89352455891786e-03;
  p = x * p;
  vec4 q = x2 * 1.19825839466702e-06 + 1.18534705686654e-04;
  q = x2 * q + 2.26843463243900e-03;
  q = x2 * q + 4.89352518554385e-03;
  return p / q;
}

// GELU's tanh (tanh form), exactly +-1 where tanh rounds there: the last ulp of mlp_tanh, times
// z^3 in the derivative, is not 0 (runtime/nn/cpu_activation.h does the same).
vec4 sn_gelu_tanh(vec4 z) {
  vec4 u = 0.7978845608028654 * (z + 0.044715 * z * z * z);
  return mix(mlp_tanh(u), sign(u), greaterThan(abs(u), vec4(9.0)));
}

#include "mlp/act_hidden.glsl"
#include "mlp/act_output.glsl"

// The activation of weight layer `l` (0-based; a literal, so the choice folds away).
#define MLP_LAYER_ACTIVATE(l, z) ((l) == MLP_LAYERS - 1 ? MLP_OUT_ACT_F(z) : MLP_ACT_F(z))
// Whether the training kernels keep f'(z) of layer l's outputs from the forward pass (in the
// units' delta slots), and that derivative.
#define MLP_LAYER_KEEPS_GRAD(l) ((l) == MLP_LAYERS - 1 ? MLP_OUT_ACT_FROM_OUTPUT == 0 : MLP_ACT_FROM_OUTPUT == 0)
#define MLP_LAYER_GRAD_Z(l, z) ((l) == MLP_LAYERS - 1 ? MLP_OUT_ACT_GRAD_Z(z) : MLP_ACT_GRAD_Z(z))
// f'(z) of a hidden (MLP_ACT_DERIV) or output (MLP_OUT_ACT_DERIV) unit vec4 from its output `a`
// or from what the forward pass kept (`kept`, not read when the output suffices).
#if MLP_ACT_FROM_OUTPUT
#define MLP_ACT_DERIV(a, kept) MLP_ACT_GRAD_A(a)
#else
#define MLP_ACT_DERIV(a, kept) (kept)
#endif
#if MLP_OUT_ACT_FROM_OUTPUT
#define MLP_OUT_ACT_DERIV(a, kept) MLP_OUT_ACT_GRAD_A(a)
#else
#define MLP_OUT_ACT_DERIV(a, kept) (kept)
#endif

// 1 for the units 4q..4q+3 that exist in a block of `width`, 0 for the padding.
bvec4 mlp_live(int q, int width) { return lessThan(ivec4(4 * q) + ivec4(0, 1, 2, 3), ivec4(width)); }

// The activations of nn::Activation by id (MLP_ACT for hidden layers, MLP_OUT_ACT for the
// output layer), chosen at compile time. Derivatives are written through the activation's
// output a = f(z), which the backward pass already holds (the oracle's f'(z), same values).
#define MLP_LINEAR 0
#define MLP_TANH 1
#define MLP_SIGMOID 2
#define MLP_RELU 3
#define MLP_LEAKY_RELU 4

// The activation of layer `l` (0-based weight layer): the output layer has its own.
#define MLP_LAYER_ACT(l) ((l) == MLP_LAYERS - 1 ? MLP_OUT_ACT : MLP_ACT)

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

vec4 mlp_activate(int kind, vec4 z) {
  if (kind == MLP_TANH) return mlp_tanh(z);
  if (kind == MLP_SIGMOID) return 1.0 / (1.0 + exp(-z));
  if (kind == MLP_RELU) return mix(vec4(0.0), z, greaterThan(z, vec4(0.0)));
  if (kind == MLP_LEAKY_RELU) return mix(MLP_SLOPE * z, z, greaterThan(z, vec4(0.0)));
  return z;
}

vec4 mlp_activate_grad(int kind, vec4 a) {
  if (kind == MLP_TANH) return 1.0 - a * a;
  if (kind == MLP_SIGMOID) return a * (1.0 - a);
  if (kind == MLP_RELU) return mix(vec4(0.0), vec4(1.0), greaterThan(a, vec4(0.0)));
  if (kind == MLP_LEAKY_RELU) return mix(vec4(MLP_SLOPE), vec4(1.0), greaterThan(a, vec4(0.0)));
  return vec4(1.0);
}

// 1 for the units 4q..4q+3 that exist in a block of `width`, 0 for the padding.
bvec4 mlp_live(int q, int width) { return lessThan(ivec4(4 * q) + ivec4(0, 1, 2, 3), ivec4(width)); }

// One Adam step (Kingma & Ba, Algorithm 1) for four parameters, exactly as nn/trainer.h writes
// it: bc1 = 1 - beta1^t and bc2 = 1 - beta2^t for this step's t. Updates the moments, returns
// the new parameters; `live` keeps padding (see mlp_live) at exactly 0.
vec4 mlp_adam(inout vec4 m, inout vec4 v, vec4 w, vec4 g, float lr, float beta1, float beta2, float eps, float bc1,
              float bc2, bvec4 live) {
  m = mix(vec4(0.0), beta1 * m + (1.0 - beta1) * g, live);
  v = mix(vec4(0.0), beta2 * v + (1.0 - beta2) * g * g, live);
  return mix(vec4(0.0), w - lr * (m / bc1) / (sqrt(v / bc2) + eps), live);
}

// Finite by its bits: a compiler may fold isnan(x) away under fast-math assumptions, this it cannot.
bool mlp_finite(float x) { return (floatBitsToUint(x) & 0x7f800000u) != 0x7f800000u; }
bool mlp_finite(vec4 x) { return all(notEqual(floatBitsToUint(x) & 0x7f800000u, uvec4(0x7f800000u))); }

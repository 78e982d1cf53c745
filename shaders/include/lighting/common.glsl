// Constants and guarded operations shared by the lighting models. CPU twin:
// runtime/shading/lighting.cpp (same constants, same guards), docs/lighting.md.
const float PI = 3.14159265358979;
const float LIGHTING_MIN_LENGTH2 = 1e-30;      // a shorter vector counts as zero
const float LIGHTING_MIN_ALPHA = 1e-3;         // GGX width floor: a mirror is a delta no pixel shows
const float LIGHTING_MIN_DENOMINATOR = 1e-30;

// x / |x|, or the zero vector when |x|^2 < 1e-30 (normalize(0) is NaN, and a shorter vector
// would come out of a clamped inverse length neither zero nor unit). A vector longer than
// 1.8e19 is first scaled by its largest component: its square overflows float, and
// inversesqrt(inf) = 0 made it zero (the double twin has no such limit).
vec3 safe_normalize(vec3 x) {
  float x2 = dot(x, x);
  if (isinf(x2)) {
    x /= max(max(abs(x.x), abs(x.y)), abs(x.z));
    x2 = dot(x, x);
  }
  return x2 >= LIGHTING_MIN_LENGTH2 ? x * inversesqrt(x2) : vec3(0.0);
}

// max(cos t, 0)^e for the angle t between a and b (any lengths), 0^0 = 1 (GLSL leaves pow(0, 0)
// undefined). A sharp lobe lives where cos t is within a few ulps of 1, where pow(dot, e) would
// multiply float's rounding by e; there the power is taken as (1 - sin^2 t)^(e/2) with sin^2 t
// from the cross product (log(1 - s) by its series for small s). Far from the peak
// (sin^2 t >= 1/2) the dot itself is the precise quantity.
float cos_lobe(vec3 a, vec3 b, float e) {
  float d = dot(a, b);
  float aa = dot(a, a) * dot(b, b);
  if (!(d > 0.0) || !(aa > LIGHTING_MIN_LENGTH2)) return e == 0.0 ? 1.0 : 0.0;
  vec3 c = cross(a, b);
  float s = clamp(dot(c, c) / aa, 0.0, 1.0);  // sin^2 t
  if (s >= 0.5) return pow(min(d * inversesqrt(aa), 1.0), e);
  float log_cos2 = s < 0.05 ? -s * (1.0 + s * (1.0 / 2.0 + s * (1.0 / 3.0 + s * (1.0 / 4.0 + s * (1.0 / 5.0 + s / 6.0)))))
                            : log(1.0 - s);
  return exp(0.5 * e * log_cos2);
}

float clamp_dot(vec3 a, vec3 b) { return clamp(dot(a, b), -1.0, 1.0); }

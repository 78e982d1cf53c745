// The thesis' three-colour toon shading (section 4.4): the Phong reflectance S_p picks one of
// C_a, mix(C_a, C_d, a), C_d, mix(C_d, C_s, a), C_s at thresholds t1 <= t2 <= t3 <= t4.
#include "lighting/phong.glsl"

vec3 toon3(float s, vec3 c_a, vec3 c_d, vec3 c_s, float a, vec4 t) {
  if (s < t.x) return c_a;
  if (s < t.y) return (1.0 - a) * c_a + a * c_d;
  if (s < t.z) return c_d;
  if (s < t.w) return (1.0 - a) * c_d + a * c_s;
  return c_s;
}

// Phong's model as the thesis writes it (section 2.2):
//   S_p = C_p [max(n.l, 0)(1 - d) + d] + W max(r.v, 0)^n,  r = 2 (n.l) n - l,
// the specular term only where the light is in front (n.l > 0). C_p and W are RGB.
#include "lighting/common.glsl"

vec3 phong(vec3 n, vec3 v, vec3 l, vec3 color, float ambient, vec3 specular, float shininess) {
  float nl = clamp_dot(n, l);
  vec3 diffuse = color * (max(nl, 0.0) * (1.0 - ambient) + ambient);
  if (!(nl > 0.0)) return diffuse;
  vec3 r = 2.0 * nl * n - l;
  return diffuse + specular * cos_lobe(r, v, shininess);
}

// The scalar S_p toon3 thresholds (C_p = 1, scalar W).
float phong_reflectance(vec3 n, vec3 v, vec3 l, float ambient, float specular, float shininess) {
  return phong(n, v, l, vec3(1.0), ambient, vec3(specular), shininess).x;
}

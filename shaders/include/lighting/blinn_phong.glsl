// Blinn-Phong: Phong with Blinn's half-vector lobe max(n.h, 0)^n, h = normalize(l + v).
#include "lighting/common.glsl"

vec3 blinn_phong(vec3 n, vec3 v, vec3 l, vec3 color, float ambient, vec3 specular, float shininess) {
  float nl = clamp_dot(n, l);
  vec3 diffuse = color * (max(nl, 0.0) * (1.0 - ambient) + ambient);
  if (!(nl > 0.0)) return diffuse;
  vec3 h = safe_normalize(l + v);  // v = -l gives h = 0: no highlight
  return diffuse + specular * cos_lobe(n, h, shininess);
}

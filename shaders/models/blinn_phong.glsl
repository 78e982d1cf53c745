// Blinn-Phong: Phong with the half-vector lobe max(n.h, 0)^n.
#include "lighting/blinn_phong.glsl"

vec3 shade(Surface s, Params p) {
  return s.light_color * blinn_phong(s.n, s.v, s.l, p.color, p.ambient, p.specular, p.shininess);
}

// Phong with the diffuse colour modulated by the mesh's base-colour texture (section 4.5).
#include "lighting/phong.glsl"

vec3 shade(Surface s, Params p) {
  return s.light_color * phong(s.n, s.v, s.l, p.color * clamp(s.base_color, 0.0, 1.0), p.ambient, p.specular, p.shininess);
}

// Phong's reflectance (the thesis' section 2.2) as a registered lighting model; the function
// itself is in shaders/include/lighting/phong.glsl, shared with toon3.
#include "lighting/phong.glsl"

vec3 shade(Surface s, Params p) {
  return s.light_color * phong(s.n, s.v, s.l, p.color, p.ambient, p.specular, p.shininess);
}

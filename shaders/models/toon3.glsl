// The thesis' three-colour toon shading (section 4.4) over the Phong reflectance S_p; its
// colours are its own, so the light's colour is not used.
#include "lighting/phong.glsl"
#include "lighting/toon3.glsl"

vec3 shade(Surface s, Params p) {
  float sp = phong_reflectance(s.n, s.v, s.l, p.ambient_weight, p.specular_weight, p.shininess);
  return toon3(sp, p.ambient, p.diffuse, p.specular, p.a, p.thresholds);
}

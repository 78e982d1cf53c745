// Cook-Torrance with the GGX distribution, height-correlated Smith visibility and Schlick's
// Fresnel (docs/lighting.md).
#include "lighting/ggx.glsl"

vec3 shade(Surface s, Params p) {
  return ggx(s.n, s.v, s.l, p.roughness, p.f0, p.diffuse, p.ambient, s.light_color);
}

// Cook-Torrance microfacet BRDF with the GGX / Trowbridge-Reitz distribution D, the
// height-correlated Smith masking-shadowing term (as the visibility V = G2 / (4 n.l n.v)) and
// Schlick's Fresnel F with an RGB F0, lit by a directional light of colour E:
//   L = A (rho_d + F0) + E [rho_d + pi D V F] n.l
// (E is scaled by pi so that a white Lambertian surface facing the light returns E).
#include "lighting/common.glsl"

// D(h) for unit n, h: alpha^2 / (pi ((n.h)^2 (alpha^2 - 1) + 1)^2), with 1 - (n.h)^2 written as
// |n x h|^2 to keep its precision where the lobe peaks.
float ggx_distribution(vec3 n, vec3 h, float alpha) {
  vec3 nxh = cross(n, h);
  float nh = dot(n, h);
  float d = dot(nxh, nxh) + nh * nh * alpha * alpha;
  return alpha * alpha / (PI * max(d * d, LIGHTING_MIN_DENOMINATOR));
}

// V n.l with V = 0.5 / (n.l sqrt((n.v)^2 (1 - a^2) + a^2) + n.v sqrt((n.l)^2 (1 - a^2) + a^2)).
float smith_visibility_nl(float nl, float nv, float alpha) {
  float a2 = alpha * alpha;
  float gv = nl * sqrt(nv * nv * (1.0 - a2) + a2);
  float gl = nv * sqrt(nl * nl * (1.0 - a2) + a2);
  return 0.5 * nl / max(gv + gl, LIGHTING_MIN_DENOMINATOR);
}

vec3 fresnel_schlick(vec3 f0, float vh) {
  float m = 1.0 - clamp(vh, 0.0, 1.0);
  float m5 = (m * m) * (m * m) * m;
  return f0 + (vec3(1.0) - f0) * m5;
}

vec3 ggx(vec3 n, vec3 v, vec3 l, float roughness, vec3 f0, vec3 diffuse, vec3 ambient_light, vec3 light_color) {
  vec3 outv = ambient_light * (diffuse + f0);
  float nl = clamp_dot(n, l);
  if (!(nl > 0.0)) return outv;
  vec3 brdf = diffuse * nl;
  float nv = clamp_dot(n, v);
  vec3 lv = l + v;
  if (nv > 0.0 && dot(lv, lv) > LIGHTING_MIN_LENGTH2) {  // seen from above, and h defined
    float alpha = max(roughness * roughness, LIGHTING_MIN_ALPHA);
    vec3 h = safe_normalize(lv);
    float d = ggx_distribution(n, h, alpha);
    float vis = smith_visibility_nl(nl, nv, alpha);
    brdf += PI * d * vis * fresnel_schlick(f0, dot(v, h));
  }
  return outv + light_color * brdf;
}

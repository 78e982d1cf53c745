// Anisotropic GGX (Burley 2012; Heitz 2014 for the height-correlated Smith term): the built-in
// GGX with a width per tangent direction, alpha_x = roughness_x^2 along the surface tangent and
// alpha_y = roughness_y^2 along the bitangent (each at least 1e-3). With equal roughnesses it is
// the built-in ggx exactly. Twin: aniso_ggx.lua; formula and domain: docs/lighting.md.
//   D = 1 / (pi ax ay ((h.t/ax)^2 + (h.b/ay)^2 + (h.n)^2)^2)
//   V n.l = 0.5 n.l / (n.l sqrt((n.v)^2 + ax^2 (v.t)^2 + ay^2 (v.b)^2) + n.v sqrt((n.l)^2 + ...))
//   S = A (rho_d + F0) + E [rho_d + pi D V F] n.l   (the lobe only where n.l > 0 and n.v > 0)
#include "lighting/ggx.glsl"

// The part of unit `x` perpendicular to unit n, normalised, or zero when x lies within about
// 0.06 degrees of n: below that the direction is float rounding, not data.
vec3 perpendicular(vec3 n, vec3 x) {
  vec3 r = x - n * dot(n, x);
  float r2 = dot(r, r);
  return r2 > 1e-6 ? r * inversesqrt(r2) : vec3(0.0);
}

// The tangent made perpendicular to n; where it has no such part (zero, or along n), the
// G-buffer's fallback frame (+X, else +Z, projected onto the tangent plane).
vec3 aniso_tangent(vec3 n, vec3 t) {
  vec3 u = perpendicular(n, t);
  if (dot(u, u) < 0.5) u = perpendicular(n, vec3(1.0, 0.0, 0.0));
  if (dot(u, u) < 0.5) u = perpendicular(n, vec3(0.0, 0.0, 1.0));
  return u;
}

vec3 shade(Surface s, Params p) {
  vec3 n = s.n, v = s.v, l = s.l;
  vec3 out_ = p.ambient * (p.diffuse + p.f0);
  float nl = clamp_dot(n, l);
  if (!(nl > 0.0)) return out_;
  vec3 brdf = p.diffuse * nl;
  float nv = clamp_dot(n, v);
  vec3 lv = l + v;
  if (nv > 0.0 && dot(lv, lv) > LIGHTING_MIN_LENGTH2) {
    float ax = max(p.roughness_x * p.roughness_x, LIGHTING_MIN_ALPHA);
    float ay = max(p.roughness_y * p.roughness_y, LIGHTING_MIN_ALPHA);
    vec3 t = aniso_tangent(n, s.tangent), b = cross(n, t);
    vec3 h = safe_normalize(lv);
    float ht = dot(h, t) / ax, hb = dot(h, b) / ay, hn = dot(h, n);
    float d = ht * ht + hb * hb + hn * hn;
    float dist = 1.0 / (PI * ax * ay * max(d * d, LIGHTING_MIN_DENOMINATOR));
    float vt = ax * dot(v, t), vb = ay * dot(v, b), lt = ax * dot(l, t), lb = ay * dot(l, b);
    float vis = 0.5 * nl / max(nl * sqrt(nv * nv + vt * vt + vb * vb) + nv * sqrt(nl * nl + lt * lt + lb * lb),
                               LIGHTING_MIN_DENOMINATOR);
    brdf += PI * dist * vis * fresnel_schlick(p.f0, dot(v, h));
  }
  return out_ + s.light_color * brdf;
}

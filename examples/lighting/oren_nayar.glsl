// Oren-Nayar diffuse reflection (Oren & Nayar 1994, the "qualitative model", their eq. 30) for a
// rough surface of V-cavities with slope deviation sigma (radians), written with the thesis'
// Phong conventions: no 1/pi (albedo is the reflectance at normal incidence, like Phong's C_p)
// and an ambient share d. Twin: oren_nayar.lua. Formula and domain: docs/lighting.md.
//   S = albedo [d + (1 - d) max(n.l, 0) (A + B max(cos(phi_i - phi_r), 0) sin(alpha) tan(beta))]
//   A = 1 - 0.5 s^2 / (s^2 + 0.33), B = 0.45 s^2 / (s^2 + 0.09),
//   alpha = max(theta_i, theta_r), beta = min(theta_i, theta_r).
vec3 shade(Surface s, Params p) {
  float nl = clamp(dot(s.n, s.l), -1.0, 1.0), nv = clamp(dot(s.n, s.v), -1.0, 1.0);
  float s2 = p.sigma * p.sigma;
  float a = 1.0 - 0.5 * s2 / (s2 + 0.33), b = 0.45 * s2 / (s2 + 0.09);
  float rough = 0.0;
  if (nl > 0.0 && nv > 0.0) {
    // Azimuths of l and v about n: their projections onto the tangent plane (zero at the pole).
    float cos_phi = max(dot(safe_normalize(s.l - s.n * nl), safe_normalize(s.v - s.n * nv)), 0.0);
    // Sines from |n x l| and |n x v|: sqrt(1 - cos^2) loses float's precision near the normal.
    float sin_i = length(cross(s.n, s.l)), sin_r = length(cross(s.n, s.v));
    float sin_alpha = nl < nv ? sin_i : sin_r;
    float tan_beta = nl < nv ? sin_r / nv : sin_i / nl;
    rough = b * cos_phi * sin_alpha * tan_beta;
  }
  return s.light_color * p.albedo * (p.ambient + (1.0 - p.ambient) * max(nl, 0.0) * (a + rough));
}

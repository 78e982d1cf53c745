// Minnaert's limb darkening (the moon's look): albedo (n.l)^k (n.v)^(k - 1). Used by
// examples/lighting/live_model.lua; edit and save it while that script runs live.
vec3 shade(Surface s, Params p) {
  float nl = max(dot(s.n, s.l), 0.0), nv = max(dot(s.n, s.v), 0.0);
  if (!(nl > 0.0 && nv > 0.0)) return vec3(0.0);
  return s.light_color * p.albedo * pow(nl, p.k) * pow(nv, p.k - 1.0);
}

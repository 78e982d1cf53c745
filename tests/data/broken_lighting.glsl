// A lighting model with an error on line 4 (tests/errors/lighting_define_glsl_error.lua).
vec3 shade(Surface s, Params p) {
  float nl = max(dot(s.n, s.l), 0.0);
  return vec3(nl * brightness);
}

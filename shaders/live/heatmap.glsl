// The live view's absolute-error heatmap (twin: runtime/live/compose.cpp, error_heat), in the
// colours of the figures' heatmaps (io/figure.h): e = mean |network - truth| over RGB,
// u = clamp(e / scale, 0, 1), mapped through the colormap's 10 control points.
uniform vec3 u_colormap[10];

vec3 colormap_at(float u) {
  float f = u * 9.0;
  int i = min(8, int(f));
  return mix(u_colormap[i], u_colormap[i + 1], f - float(i));
}

vec4 error_heat(vec4 network, vec4 truth, float scale) {
  bool covered = network.a > 0.5 || truth.a > 0.5;
  if (!covered) return vec4(0.0);
  if (any(isnan(network.rgb)) || any(isinf(network.rgb))) return vec4(1.0, 0.0, 1.0, 1.0);  // never hidden
  vec3 d = abs(network.rgb - truth.rgb);
  return vec4(colormap_at(clamp((d.r + d.g + d.b) / 3.0 / scale, 0.0, 1.0)), 1.0);
}

// Live view composition: LAYOUT_SIDE = truth | network | error heatmap side by side,
// otherwise the error heatmap alone. One invocation per output pixel.
#include "heatmap.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D u_network;
layout(binding = 1) uniform sampler2D u_truth;
layout(binding = 0, rgba32f) uniform writeonly image2D u_out;
uniform ivec2 u_panel;  // size of one input image
uniform float u_scale;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(u_out);
  if (p.x >= size.x || p.y >= size.y) return;
#if LAYOUT_SIDE
  int panel = p.x / u_panel.x;
  ivec2 q = ivec2(p.x - panel * u_panel.x, p.y);
#else
  int panel = 2;
  ivec2 q = p;
#endif
  vec4 n = texelFetch(u_network, q, 0);
  vec4 t = texelFetch(u_truth, q, 0);
  vec4 c = panel == 0 ? t : panel == 1 ? n : error_heat(n, t, u_scale);
  imageStore(u_out, p, c);
}

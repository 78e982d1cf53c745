// Live view composition: LAYOUT_SIDE = truth | network over error heatmap | (empty), 2 x 2,
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
  // 2 x 2 panels, top row first: truth | network, error | nothing (GL rows start at the bottom).
  int col = p.x / u_panel.x, row = p.y >= u_panel.y ? 0 : 1;
  int panel = row * 2 + col;
  ivec2 q = ivec2(p.x - col * u_panel.x, p.y - (row == 0 ? u_panel.y : 0));
  if (panel == 3) {
    imageStore(u_out, p, vec4(0.0));
    return;
  }
#else
  int panel = 2;
  ivec2 q = p;
#endif
  vec4 n = texelFetch(u_network, q, 0);
  vec4 t = texelFetch(u_truth, q, 0);
  vec4 c = panel == 0 ? t : panel == 1 ? n : error_heat(n, t, u_scale);
  imageStore(u_out, p, c);
}

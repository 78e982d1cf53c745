// Converts a buffer of colours between RGB and COLOR_SPACE (color.glsl): TO_RGB = 0 encodes
// RGB into the space, TO_RGB = 1 decodes back. Used by the colour twin tests and by scripts
// that turn network outputs into RGB.
layout(local_size_x = 64) in;

#include "color.glsl"

layout(std430, binding = 0) readonly buffer Inputs { vec4 inputs[]; };
layout(std430, binding = 1) writeonly buffer Outputs { vec4 outputs[]; };

uniform uint u_first;
uniform uint u_count;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= u_count) return;
  i += u_first;
#if TO_RGB
  outputs[i] = vec4(color_to_rgb(inputs[i].xyz), inputs[i].w);
#else
  outputs[i] = vec4(color_from_rgb(inputs[i].xyz), inputs[i].w);
#endif
}

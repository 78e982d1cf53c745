// Shades compact sample buffers with one lighting model: one invocation per sample. Used to
// build datasets (covered pixels gathered by shaders/gather.comp) and by the CPU-twin and
// stress tests. Defines: LIGHTING_MODEL (lighting/model.glsl), COLOR_SPACE (color.glsl) for
// the stored target, LIGHTING_RAW = 1 to store the unclamped RGB radiance instead.
layout(local_size_x = 64) in;

#include "lighting/model.glsl"
#include "color.glsl"

layout(std430, binding = 0) readonly buffer Normals { vec4 normals[]; };
layout(std430, binding = 1) readonly buffer Views { vec4 views[]; };
#if LIGHTING_MODEL == LIGHTING_TEXTURED_PHONG
layout(std430, binding = 2) readonly buffer BaseColors { vec4 base_colors[]; };
#endif
layout(std430, binding = 3) writeonly buffer Targets { vec4 targets[]; };

uniform uint u_first;  // samples [u_first, u_first + u_count) in this dispatch
uniform uint u_count;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= u_count) return;
  i += u_first;
#if LIGHTING_MODEL == LIGHTING_TEXTURED_PHONG
  vec3 base = base_colors[i].rgb;
#else
  vec3 base = vec3(1.0);
#endif
#if LIGHTING_RAW
  targets[i] = vec4(lighting_raw(normals[i].xyz, views[i].xyz, base), 1.0);
#else
  targets[i] = vec4(color_from_rgb(lighting(normals[i].xyz, views[i].xyz, base)), 1.0);
#endif
}

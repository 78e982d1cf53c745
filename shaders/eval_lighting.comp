// Shades compact sample buffers with one lighting model: one invocation per sample. Used to
// build datasets (covered pixels gathered by shaders/gather.comp) and by the CPU-twin and
// stress tests. "lighting/model.glsl" is assembled per model by runtime/shading/lighting_gpu.cpp,
// which also defines SURFACE_<ATTRIBUTE> for each attribute the model reads beyond normal and
// view; COLOR_SPACE (color.glsl) is the stored target's space, LIGHTING_RAW = 1 stores the
// unclamped RGB radiance instead; LIGHTING_VARY reads parameters per sample (conditioned datasets).
layout(local_size_x = 64) in;

#include "lighting/model.glsl"
#include "color.glsl"

layout(std430, binding = 0) readonly buffer Normals { vec4 normals[]; };
layout(std430, binding = 1) readonly buffer Views { vec4 views[]; };
layout(std430, binding = 2) writeonly buffer Targets { vec4 targets[]; };
// One binding per surface attribute, in the order of sn::shading::surface_attributes().
#ifdef SURFACE_BASE_COLOR
layout(std430, binding = 3) readonly buffer BaseColors { vec4 base_colors[]; };
#endif
#ifdef SURFACE_UV
layout(std430, binding = 4) readonly buffer Uvs { vec4 uvs[]; };
#endif
#ifdef SURFACE_POSITION
layout(std430, binding = 5) readonly buffer Positions { vec4 positions[]; };
#endif
#ifdef SURFACE_WORLD_POSITION
layout(std430, binding = 6) readonly buffer WorldPositions { vec4 world_positions[]; };
#endif
#ifdef SURFACE_TANGENT
layout(std430, binding = 7) readonly buffer Tangents { vec4 tangents[]; };
#endif
#ifdef SURFACE_BITANGENT
layout(std430, binding = 8) readonly buffer Bitangents { vec4 bitangents[]; };
#endif
#ifdef LIGHTING_VARY
layout(std430, binding = 9) readonly buffer Varied { vec4 varied[]; };  // parameters set per sample
#endif

uniform uint u_first;  // samples [u_first, u_first + u_count) in this dispatch
uniform uint u_count;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= u_count) return;
  i += u_first;
  Surface s = lighting_surface(normals[i].xyz, views[i].xyz);
#ifdef SURFACE_BASE_COLOR
  s.base_color = base_colors[i].rgb;
#endif
#ifdef SURFACE_UV
  s.uv = uvs[i].xy;
#endif
#ifdef SURFACE_POSITION
  s.position = positions[i].xyz;
#endif
#ifdef SURFACE_WORLD_POSITION
  s.world_position = world_positions[i].xyz;
#endif
#ifdef SURFACE_TANGENT
  s.tangent = safe_normalize(tangents[i].xyz);
#endif
#ifdef SURFACE_BITANGENT
  s.bitangent = safe_normalize(bitangents[i].xyz);
#endif
  Params p = lighting_params();
#ifdef LIGHTING_VARY
  lighting_vary(p, varied[i]);
#endif
  vec3 raw = lighting_raw(s, p);
#if LIGHTING_RAW
  targets[i] = vec4(raw, 1.0);
#else
  // w = 0 flags radiance that is not finite: clamping would store a made-up number.
  targets[i] = vec4(color_from_rgb(clamp(raw, 0.0, 1.0)), any(isnan(raw)) || any(isinf(raw)) ? 0.0 : 1.0);
#endif
}

// Ground-truth image: the lighting model ("lighting/model.glsl", assembled per model by
// runtime/shading/lighting_gpu.cpp) at every covered pixel of a G-buffer, background left
// transparent black. Alpha = coverage. Each attribute the model reads (SURFACE_<NAME>) comes
// from the G-buffer texture u_<name>.
#include "lighting/model.glsl"

uniform sampler2D u_normal;
uniform sampler2D u_view;
#ifdef SURFACE_BASE_COLOR
uniform sampler2D u_base_color;
#endif
#ifdef SURFACE_UV
uniform sampler2D u_uv;
#endif
#ifdef SURFACE_POSITION
uniform sampler2D u_position;
#endif
#ifdef SURFACE_WORLD_POSITION
uniform sampler2D u_world_position;
#endif
#ifdef SURFACE_TANGENT
uniform sampler2D u_tangent;
#endif
#ifdef SURFACE_BITANGENT
uniform sampler2D u_bitangent;
#endif

layout(location = 0) out vec4 o_color;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec4 n = texelFetch(u_normal, p, 0);
  if (!(n.w > 0.5)) {
    o_color = vec4(0.0);
    return;
  }
  Surface s = lighting_surface(n.xyz, texelFetch(u_view, p, 0).xyz);
#ifdef SURFACE_BASE_COLOR
  s.base_color = texelFetch(u_base_color, p, 0).rgb;
#endif
#ifdef SURFACE_UV
  s.uv = texelFetch(u_uv, p, 0).xy;
#endif
#ifdef SURFACE_POSITION
  s.position = texelFetch(u_position, p, 0).xyz;
#endif
#ifdef SURFACE_WORLD_POSITION
  s.world_position = texelFetch(u_world_position, p, 0).xyz;
#endif
#ifdef SURFACE_TANGENT
  s.tangent = safe_normalize(texelFetch(u_tangent, p, 0).xyz);
#endif
#ifdef SURFACE_BITANGENT
  s.bitangent = safe_normalize(texelFetch(u_bitangent, p, 0).xyz);
#endif
  // A non-finite radiance is marked (alpha -1) for the caller to name, not clamped to a colour:
  // clamp of NaN is undefined, and it drew as black.
  vec3 raw = lighting_raw(s);
  bool finite = !any(isnan(raw)) && !any(isinf(raw));
  o_color = finite ? vec4(clamp(raw, 0.0, 1.0), 1.0) : vec4(0.0, 0.0, 0.0, -1.0);
}

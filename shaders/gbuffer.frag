// The G-buffer pass (runtime/scene/gbuffer.cpp): writes only the attributes asked for, each to
// the attachment its ATTR_<NAME> define names, value in .xyz (uv in .xy) and coverage 1 in .w
// (the target is cleared to 0, so background pixels read coverage 0).
#include "lighting/common.glsl"

in vec3 v_world_position;
in vec3 v_world_normal;
in vec2 v_uv;
in vec3 v_object_position;
in vec3 v_world_tangent;
in float v_handedness;

uniform vec3 u_eye;
uniform sampler2D u_base_color;

#ifdef ATTR_NORMAL
layout(location = ATTR_NORMAL) out vec4 o_normal;
#endif
#ifdef ATTR_VIEW
layout(location = ATTR_VIEW) out vec4 o_view;
#endif
#ifdef ATTR_POSITION
layout(location = ATTR_POSITION) out vec4 o_position;
#endif
#ifdef ATTR_WORLD_POSITION
layout(location = ATTR_WORLD_POSITION) out vec4 o_world_position;
#endif
#ifdef ATTR_UV
layout(location = ATTR_UV) out vec4 o_uv;
#endif
#ifdef ATTR_BASE_COLOR
layout(location = ATTR_BASE_COLOR) out vec4 o_base_color;
#endif
#ifdef ATTR_TANGENT
layout(location = ATTR_TANGENT) out vec4 o_tangent;
#endif
#ifdef ATTR_BITANGENT
layout(location = ATTR_BITANGENT) out vec4 o_bitangent;
#endif

void main() {
#ifdef ATTR_NORMAL
  // Two-sided: a back face (an open sheet seen from behind) shows the side facing the eye.
  vec3 n = safe_normalize(v_world_normal);
  o_normal = vec4(gl_FrontFacing ? n : -n, 1.0);
#endif
#ifdef ATTR_VIEW
  o_view = vec4(safe_normalize(u_eye - v_world_position), 1.0);
#endif
#ifdef ATTR_POSITION
  o_position = vec4(v_object_position, 1.0);
#endif
#ifdef ATTR_WORLD_POSITION
  o_world_position = vec4(v_world_position, 1.0);
#endif
#ifdef ATTR_UV
  o_uv = vec4(v_uv, 0.0, 1.0);
#endif
#ifdef ATTR_BASE_COLOR
  o_base_color = vec4(texture(u_base_color, v_uv).rgb, 1.0);
#endif
#if defined(ATTR_TANGENT) || defined(ATTR_BITANGENT)
  // The interpolated tangent made perpendicular to the interpolated normal again (Gram-Schmidt).
  // A back face keeps its tangent and bitangent while its normal turns towards the eye.
  vec3 gn = safe_normalize(v_world_normal);
  vec3 t = safe_normalize(v_world_tangent - gn * dot(gn, v_world_tangent));
#endif
#ifdef ATTR_TANGENT
  o_tangent = vec4(t, 1.0);
#endif
#ifdef ATTR_BITANGENT
  o_bitangent = vec4(sign(v_handedness) * cross(gn, t), 1.0);
#endif
}

// Ground-truth image: the lighting model (lighting/model.glsl) at every covered pixel of a
// G-buffer, background left transparent black. Alpha = coverage.
#include "lighting/model.glsl"

uniform sampler2D u_normal;
uniform sampler2D u_view;
#if LIGHTING_MODEL == LIGHTING_TEXTURED_PHONG
uniform sampler2D u_base_color;
#endif

layout(location = 0) out vec4 o_color;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec4 n = texelFetch(u_normal, p, 0);
  if (!(n.w > 0.5)) {
    o_color = vec4(0.0);
    return;
  }
#if LIGHTING_MODEL == LIGHTING_TEXTURED_PHONG
  vec3 base = texelFetch(u_base_color, p, 0).rgb;
#else
  vec3 base = vec3(1.0);
#endif
  o_color = vec4(lighting(n.xyz, texelFetch(u_view, p, 0).xyz, base), 1.0);
}

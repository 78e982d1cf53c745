// One activation's GLSL evaluated at sample points (runtime/nn/activation_define.cpp compares it
// with the Lua twin before registering a user's definition). CHECK_CALL(z) is the function under
// test: the activation or its derivative, at parameter value 0 or the network default.
layout(local_size_x = 64) in;
#include "mlp/activation.glsl"

layout(std430, binding = 0) readonly buffer Z { float zs[]; };
layout(std430, binding = 1) writeonly buffer Out { float outs[]; };  // 4 per point
uniform uint u_count;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= u_count) return;
  // Every lane a different point: a definition that mixes lanes (a swizzle, vec4(x.x)) gives one
  // unit another unit's value, and lanes y, z and w show it.
  vec4 z = vec4(zs[i], zs[(i + 1u) % u_count], zs[(i + 2u) % u_count], zs[(i + 3u) % u_count]);
  vec4 r = CHECK_CALL(z);
  for (uint k = 0u; k < 4u; ++k) outs[4u * i + k] = r[k];
}

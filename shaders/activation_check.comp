// One activation's GLSL evaluated at sample points (runtime/nn/activation_define.cpp compares it
// with the Lua twin before registering a user's definition). CHECK_CALL(z) is the function under
// test: the activation or its derivative, at parameter value 0 or the network default.
layout(local_size_x = 64) in;
#include "mlp/activation.glsl"

layout(std430, binding = 0) readonly buffer Z { float zs[]; };
layout(std430, binding = 1) writeonly buffer Out { float outs[]; };
uniform uint u_count;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= u_count) return;
  outs[i] = CHECK_CALL(vec4(zs[i])).x;
}

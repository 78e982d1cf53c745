// A network's input encodings (shaders/include/mlp/encoding.glsl) over rows of raw inputs: what
// its first layer reads, written out (runtime/nn/gl_forward.cpp gl_encode; the tests compare it
// with the double twins).
layout(local_size_x = 64) in;
#include "mlp/encoding.glsl"

layout(std430, binding = 0) readonly buffer X { float xs[]; };   // rows x MLP_RAW_IN
layout(std430, binding = 1) writeonly buffer Out { vec4 es[]; };  // rows x MLP_IN4
uniform uint u_rows;

void main() {
  uint r = gl_GlobalInvocationID.x;
  if (r >= u_rows) return;
  float raw[MLP_RAW_IN];
  for (int i = 0; i < MLP_RAW_IN; ++i) raw[i] = xs[r * uint(MLP_RAW_IN) + uint(i)];
  vec4 e[MLP_IN4];
  mlp_encode(raw, e);
  for (int q = 0; q < MLP_IN4; ++q) es[r * uint(MLP_IN4) + uint(q)] = e[q];
}

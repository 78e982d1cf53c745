// y = scale * (x^3 - 2x) + tanh(x): a small function the unit test recomputes in C++.
layout(local_size_x = LOCAL_SIZE) in;
layout(std430, binding = 0) readonly buffer In { float xs[]; };
layout(std430, binding = 1) writeonly buffer Out { float ys[]; };
uniform uint u_count;
uniform float u_scale;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= u_count) return;
  float x = xs[i];
  ys[i] = u_scale * (x * x * x - 2.0 * x) + tanh(x);
}

// y = scale * (x^3 - 2x) + tanh(x): a small function the unit test recomputes in C++.
layout(local_size_x = LOCAL_SIZE) in;
#ifdef FROM_TEXTURE  // x read through a buffer texture on unit 0
layout(binding = 0) uniform samplerBuffer u_xs;
#else
layout(std430, binding = 0) readonly buffer In { float xs[]; };
#endif
layout(std430, binding = 1) writeonly buffer Out { float ys[]; };
uniform uint u_count;
uniform float u_scale;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= u_count) return;
#ifdef FROM_TEXTURE
  float x = texelFetch(u_xs, int(i)).r;
#else
  float x = xs[i];
#endif
  ys[i] = u_scale * (x * x * x - 2.0 * x) + tanh(x);
}

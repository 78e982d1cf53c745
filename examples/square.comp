// Squares every element of a float buffer in place (examples/hello_compute.lua).
layout(local_size_x = LOCAL_SIZE) in;
layout(std430, binding = 0) buffer Values { float values[]; };
uniform uint u_count;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i < u_count) values[i] = values[i] * values[i];
}

// Two storage blocks without layout(binding = N): both sit at binding 0 (tests/errors/dispatch_shared_binding.lua).
layout(local_size_x = 1) in;
layout(std430) readonly buffer In { float xs[]; };
layout(std430) writeonly buffer Out { float ys[]; };
void main() { ys[gl_GlobalInvocationID.x] = 2.0 * xs[gl_GlobalInvocationID.x]; }

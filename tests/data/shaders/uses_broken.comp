// Includes a helper with a compile error (tests/errors/glsl_include.lua).
layout(local_size_x = 1) in;
#include "broken_helper.glsl"
layout(std430, binding = 0) buffer Out { float values[]; };

void main() { values[0] = twice(1.0); }

layout(local_size_x = 1) in;
#include "no_such_file.glsl"
void main() {}

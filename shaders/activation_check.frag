// One activation's GLSL compiled in a fragment shader, as a network's render uses it
// (runtime/nn/activation_define.cpp compiles this, and never draws it): GLSL that only a compute
// shader accepts is refused where it is defined, not at the first render.
#include "mlp/activation.glsl"

out vec4 o_color;

void main() { o_color = CHECK_CALL(vec4(gl_FragCoord.x)); }

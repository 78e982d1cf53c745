// Test shader (test_mesh.cpp): writes the interpolated uv, alpha 1 on covered pixels.
in vec2 v_uv;
layout(location = 0) out vec4 o_color;
void main() { o_color = vec4(v_uv, 0.0, 1.0); }

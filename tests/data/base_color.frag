// Test shader (test_mesh.cpp): the mesh's base-colour texture at mip level 0 (plain bilinear,
// so a CPU twin can reproduce it); alpha says whether the mesh has a texture.
in vec2 v_uv;
uniform sampler2D u_base_color;
uniform bool u_has_base_color;
layout(location = 0) out vec4 o_color;
void main() { o_color = vec4(textureLod(u_base_color, v_uv, 0.0).rgb, u_has_base_color ? 1.0 : 0.5); }

// The live tests' shading: a tint times a clamped Lambert term, alpha 1 on the mesh.
in vec3 v_world_normal;
uniform vec3 u_tint;
uniform vec3 u_light;
layout(location = 0) out vec4 o_color;

void main() {
  float lambert = max(dot(normalize(v_world_normal), normalize(u_light)), 0.15);
  o_color = vec4(u_tint * lambert, 1.0);
}

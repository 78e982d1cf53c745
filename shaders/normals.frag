// A normal map: the world-space normal mapped from [-1,1] to [0,1]. Alpha 1 marks a covered
// pixel; the cleared background keeps alpha 0 ("uncovered").
in vec3 v_world_normal;

layout(location = 0) out vec4 o_color;

void main() {
  o_color = vec4(normalize(v_world_normal) * 0.5 + 0.5, 1.0);
}

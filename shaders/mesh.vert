// The vertex stage every mesh draw can share (sn.draw): places a Mesh's vertices with the
// standard uniforms and hands world-space position, normal and tangent, uv and the
// untransformed position to the fragment stage.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
layout(location = 3) in vec4 a_tangent;  // xyz, w = handedness (runtime/scene/tangents.h)

uniform mat4 u_model;
uniform mat4 u_view;
uniform mat4 u_proj;
uniform mat3 u_normal_matrix;  // inverse transpose of u_model's 3x3: keeps normals perpendicular under scaling

out vec3 v_world_position;
out vec3 v_world_normal;  // not normalised: interpolation shortens it anyway, the fragment stage normalises
out vec2 v_uv;
out vec3 v_object_position;
out vec3 v_world_tangent;  // moves with the surface: the model matrix, not its inverse transpose
out float v_handedness;

void main() {
  vec4 world = u_model * vec4(a_position, 1.0);
  v_world_position = world.xyz;
  v_world_normal = u_normal_matrix * a_normal;
  v_uv = a_uv;
  v_object_position = a_position;
  v_world_tangent = mat3(u_model) * a_tangent.xyz;
  // A mirroring model matrix flips the frame's handedness.
  v_handedness = a_tangent.w * (determinant(mat3(u_model)) < 0.0 ? -1.0 : 1.0);
  gl_Position = u_proj * u_view * world;
}

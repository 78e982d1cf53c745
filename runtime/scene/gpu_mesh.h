// A Mesh on the GPU: one interleaved vertex buffer (location 0 position, 1 normal, 2 uv), one
// uint32 index buffer, one VAO and the base-colour texture (a 1x1 white one when the mesh has
// none). Uploaded once per Mesh and cached on it, so drawing a mesh again costs no transfer; the
// texture only when a program first samples it (decoding it loads OpenImageIO, scene/texture.h).
#pragma once
#include <cstddef>
#include <memory>

#include <glm/glm.hpp>

#include "gl/program.h"
#include "scene/camera.h"
#include "scene/mesh.h"

namespace sn::scene {

class GpuMesh {
 public:
  explicit GpuMesh(const Mesh& m);
  ~GpuMesh();
  GpuMesh(const GpuMesh&) = delete;
  GpuMesh& operator=(const GpuMesh&) = delete;

  std::size_t index_count() const { return index_count_; }
  unsigned vao() const { return vao_; }
  unsigned base_color_texture() const;
  bool has_base_color() const { return bool(texture_source_); }
  // The box around the uploaded positions (object space): what the draw can cover, whatever
  // became of Mesh::bounds since.
  const Bounds& bounds() const { return bounds_; }

  // How many GpuMesh objects were ever created (tests check that a second draw reuses one).
  static std::size_t uploads();

 private:
  unsigned vao_ = 0, vertices_ = 0, indices_ = 0;
  mutable unsigned texture_ = 0;
  std::size_t index_count_ = 0;
  Texture texture_source_;  // the mesh's at upload (a copy sharing its pixels)
  Bounds bounds_;
};

// The GPU copy of `m`, uploading it on first use (cached in m.gpu).
GpuMesh& upload(const Mesh& m);

enum class Cull { none, back, front };

// The texture unit the mesh's base-colour texture is bound to for `u_base_color`.
constexpr int kBaseColorUnit = 15;

// Sets the standard uniforms `p` declares (any it does not declare are skipped):
//   mat4 u_model, u_view, u_proj; mat3 u_normal_matrix (inverse transpose of u_model's 3x3);
//   vec3 u_eye (world space); sampler2D u_base_color; bool u_has_base_color.
void set_standard_uniforms(gl::Program& p, const Camera& camera, double aspect, const glm::dmat4& model,
                           const GpuMesh& mesh);

// Draws the mesh's triangles with `p` into whatever framebuffer is bound (depth test as set by
// RenderTarget::bind). A model matrix that mirrors (negative determinant) reverses the
// triangles' winding on screen, so the front face is then the clockwise one: gl_FrontFacing and
// culling see the mesh's own sides. Throws for a compute program.
void draw(gl::Program& p, const GpuMesh& mesh, const glm::dmat4& model, Cull cull = Cull::none);

}  // namespace sn::scene

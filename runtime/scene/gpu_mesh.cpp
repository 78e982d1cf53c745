#include "scene/gpu_mesh.h"
#include "scene/tangents.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <glm/gtc/type_ptr.hpp>

namespace sn::scene {

namespace {

std::atomic<std::size_t> g_uploads{0};

struct Vertex {
  glm::vec3 position, normal;
  glm::vec2 uv;
  glm::vec4 tangent;  // xyz, w = handedness (tangents.h)
};

// RGBA8 texels of an image with 1-4 channels (grey -> rgb, missing alpha -> 1). Rows stay top
// first, so texture(v = 0) is the image's top row: glTF's UV convention, no flip needed.
// The texture as RGBA floats (grey to all three, alpha 1 where it has none; NaN and Inf as 0), and
// whether every value is an 8-bit one (k / 255), as every 8-bit file's are: those upload as
// RGBA8, the rest (16-bit files, images made in a script) as RGBA32F, unclamped and unrounded as
// the CPU twin reads them (they were clamped to [0, 1] and rounded to 8 bits).
std::vector<float> rgba(const io::Image& img, bool& eight_bit) {
  std::vector<float> out(size_t(img.width) * img.height * 4);
  eight_bit = true;
  auto finite = [&](float v) {
    v = std::isfinite(v) ? v : 0.f;
    eight_bit = eight_bit && v >= 0.f && v <= 1.f && std::abs(v * 255.f - std::nearbyint(v * 255.f)) < 1e-3f;
    return v;
  };
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      float* o = &out[(size_t(y) * img.width + x) * 4];
      int c = img.channels;
      float r = img.at(x, y, 0);
      float g = c >= 3 ? img.at(x, y, 1) : r, b = c >= 3 ? img.at(x, y, 2) : r;
      float a = c == 2 ? img.at(x, y, 1) : c == 4 ? img.at(x, y, 3) : 1.f;
      o[0] = finite(r), o[1] = finite(g), o[2] = finite(b), o[3] = finite(a);
    }
  return out;
}

}  // namespace

GpuMesh::GpuMesh(const Mesh& m) {
  validate(m);
  std::vector<Vertex> verts(m.positions.size());
  const std::vector<glm::vec4> tangents = mesh_tangents(m);
  for (size_t i = 0; i < verts.size(); ++i) verts[i] = {m.positions[i], m.normals[i], m.uvs[i], tangents[i]};
  index_count_ = m.indices.size();
  bounds_ = compute_bounds(m.positions);

  glCreateBuffers(1, &vertices_);
  glNamedBufferStorage(vertices_, GLsizeiptr(std::max<size_t>(verts.size(), 1) * sizeof(Vertex)),
                       verts.empty() ? nullptr : verts.data(), 0);
  glCreateBuffers(1, &indices_);
  glNamedBufferStorage(indices_, GLsizeiptr(std::max<size_t>(index_count_, 1) * 4),
                       index_count_ ? m.indices.data() : nullptr, 0);
  glCreateVertexArrays(1, &vao_);
  glVertexArrayVertexBuffer(vao_, 0, vertices_, 0, sizeof(Vertex));
  glVertexArrayElementBuffer(vao_, indices_);
  const GLuint offsets[4] = {offsetof(Vertex, position), offsetof(Vertex, normal), offsetof(Vertex, uv),
                             offsetof(Vertex, tangent)};
  const GLint sizes[4] = {3, 3, 2, 4};
  for (GLuint a = 0; a < 4; ++a) {
    glEnableVertexArrayAttrib(vao_, a);
    glVertexArrayAttribFormat(vao_, a, sizes[a], GL_FLOAT, GL_FALSE, offsets[a]);
    glVertexArrayAttribBinding(vao_, a, 0);
  }

  texture_source_ = m.base_color;
  ++g_uploads;
}

unsigned GpuMesh::base_color_texture() const {
  if (texture_) return texture_;
  io::Image white(1, 1, 4, 1.f);
  const io::Image& img = texture_source_ ? *texture_source_ : white;
  bool eight_bit = true;
  const std::vector<float> texels = rgba(img, eight_bit);
  int levels = 1;
  for (int s = std::max(img.width, img.height); s > 1; s /= 2) ++levels;
  glCreateTextures(GL_TEXTURE_2D, 1, &texture_);
  glTextureStorage2D(texture_, levels, eight_bit ? GL_RGBA8 : GL_RGBA32F, img.width, img.height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureSubImage2D(texture_, 0, 0, 0, img.width, img.height, GL_RGBA, GL_FLOAT, texels.data());
  glGenerateTextureMipmap(texture_);
  // Wrapped and filtered as the file's sampler says.
  const Sampler& sampler = texture_source_.sampler;
  glTextureParameteri(texture_, GL_TEXTURE_WRAP_S, gl_value(sampler.s));
  glTextureParameteri(texture_, GL_TEXTURE_WRAP_T, gl_value(sampler.t));
  glTextureParameteri(texture_, GL_TEXTURE_MIN_FILTER, gl_value(sampler.min));
  glTextureParameteri(texture_, GL_TEXTURE_MAG_FILTER, gl_value(sampler.mag));
  return texture_;
}

GpuMesh::~GpuMesh() {
  glDeleteVertexArrays(1, &vao_);
  glDeleteBuffers(1, &vertices_);
  glDeleteBuffers(1, &indices_);
  glDeleteTextures(1, &texture_);
}

std::size_t GpuMesh::uploads() { return g_uploads; }

GpuMesh& upload(const Mesh& m) {
  if (!m.gpu) m.gpu = std::make_shared<GpuMesh>(m);
  return *m.gpu;
}

namespace {

std::vector<double> numbers(const glm::dmat4& m) {
  const double* p = glm::value_ptr(m);
  return std::vector<double>(p, p + 16);
}
std::vector<double> numbers(const glm::dmat3& m) {
  const double* p = glm::value_ptr(m);
  return std::vector<double>(p, p + 9);
}

}  // namespace

void set_standard_uniforms(gl::Program& p, const Camera& camera, double aspect, const glm::dmat4& model,
                           const GpuMesh& mesh) {
  auto set = [&](const char* name, const std::vector<double>& v) {
    if (p.uniform(name)) p.set_uniform(name, v);
  };
  set("u_model", numbers(model));
  set("u_view", numbers(camera.view()));
  set("u_proj", numbers(camera.projection(aspect)));
  if (p.uniform("u_normal_matrix")) {
    glm::dmat3 linear(model);
    if (!(std::abs(glm::determinant(linear)) > 1e-300))
      throw std::invalid_argument("draw: the model matrix is singular, so normals cannot be transformed");
    set("u_normal_matrix", numbers(glm::transpose(glm::inverse(linear))));
  }
  const glm::dvec3& e = camera.eye();
  set("u_eye", {e.x, e.y, e.z});
  if (p.uniform("u_base_color")) {
    glBindTextureUnit(kBaseColorUnit, mesh.base_color_texture());
    set("u_base_color", {double(kBaseColorUnit)});
  }
  set("u_has_base_color", {mesh.has_base_color() ? 1.0 : 0.0});
}

void draw(gl::Program& p, const GpuMesh& mesh, const glm::dmat4& model, Cull cull) {
  if (p.is_compute()) throw std::invalid_argument("draw needs a vertex + fragment program, got compute " + p.name());
  if (cull == Cull::none) {
    glDisable(GL_CULL_FACE);
  } else {
    glEnable(GL_CULL_FACE);
    glCullFace(cull == Cull::back ? GL_BACK : GL_FRONT);
  }
  glFrontFace(glm::determinant(glm::dmat3(model)) < 0 ? GL_CW : GL_CCW);
  glUseProgram(p.id());
  glBindVertexArray(mesh.vao());
  glDrawElements(GL_TRIANGLES, GLsizei(mesh.index_count()), GL_UNSIGNED_INT, nullptr);
  glBindVertexArray(0);
  glDisable(GL_CULL_FACE);
  glFrontFace(GL_CCW);
}

}  // namespace sn::scene

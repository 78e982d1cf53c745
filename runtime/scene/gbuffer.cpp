#include "scene/gbuffer.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>

#include "scene/camera.h"
#include "scene/gpu_mesh.h"
#include "scene/mesh.h"

namespace sn::scene {

namespace {

std::size_t g_renders = 0;

// The #define that switches each attribute on in shaders/gbuffer.frag.
std::string define_name(const std::string& attribute) {
  std::string d = "ATTR_";
  for (char c : attribute) d += char(std::toupper(static_cast<unsigned char>(c)));
  return d;
}

std::string valid_names() {
  std::string s;
  for (const auto& n : gbuffer_attribute_names()) s += (s.empty() ? "" : ", ") + n;
  return s;
}

// The pixels the corners of `b` (object space) can reach through `clip` = projection x view x
// model, one pixel wider on each side; false when a corner lies on or behind the eye's plane,
// where the projection of the box is not the box of its corners' projections.
bool projected_box(const Bounds& b, const glm::dmat4& clip, int width, int height, PixelBox* out) {
  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  for (int c = 0; c < 8; ++c) {
    const glm::dvec4 p = clip * glm::dvec4(c & 1 ? b.max.x : b.min.x, c & 2 ? b.max.y : b.min.y,
                                           c & 4 ? b.max.z : b.min.z, 1.0);
    if (!(p.w > 1e-9)) return false;
    for (int k = 0; k < 2; ++k) {
      const double v = p[k] / p.w;
      lo[k] = std::min(lo[k], v), hi[k] = std::max(hi[k], v);
    }
  }
  // NDC -> pixels; a pixel is covered when its centre (i + 0.5) is inside.
  const auto px = [](double ndc, int size) { return (ndc * 0.5 + 0.5) * size; };
  const auto clamp = [](double v, int size) { return int(std::max(0.0, std::min(double(size), v))); };
  out->x0 = clamp(std::floor(px(lo[0], width)) - 1, width);
  out->x1 = clamp(std::ceil(px(hi[0], width)) + 1, width);
  out->y0 = clamp(std::floor(px(lo[1], height)) - 1, height);
  out->y1 = clamp(std::ceil(px(hi[1], height)) + 1, height);
  return true;
}

}  // namespace

const std::vector<std::string>& gbuffer_attribute_names() {
  static const std::vector<std::string> names = {"normal",     "view",       "position", "world_position",
                                                 "uv",         "base_color", "tangent",  "bitangent"};
  return names;
}

int attribute_width(const std::string& name) {
  const auto& names = gbuffer_attribute_names();
  if (std::find(names.begin(), names.end(), name) == names.end())
    throw std::invalid_argument("unknown G-buffer attribute '" + name + "' (valid: " + valid_names() + ")");
  return name == "uv" ? 2 : 3;
}

int GBuffer::attachment(const std::string& name) const {
  for (std::size_t i = 0; i < attributes.size(); ++i)
    if (attributes[i] == name) return int(i);
  std::string held;
  for (const auto& a : attributes) held += (held.empty() ? "" : ", ") + a;
  throw std::invalid_argument("this G-buffer has no attribute '" + name + "' (it holds: " + held + ")");
}

void check_attributes(const std::vector<std::string>& attributes) {
  if (attributes.empty()) throw std::invalid_argument("a G-buffer needs at least one attribute (valid: " + valid_names() + ")");
  if (attributes.size() > 6)  // shaders/gather.comp compacts at most 6
    throw std::invalid_argument("a G-buffer holds at most 6 attributes, asked for " + std::to_string(attributes.size()));
  for (std::size_t i = 0; i < attributes.size(); ++i) {
    attribute_width(attributes[i]);
    for (std::size_t j = 0; j < i; ++j)
      if (attributes[j] == attributes[i])
        throw std::invalid_argument("G-buffer attribute '" + attributes[i] + "' is listed twice");
  }
}

GBuffer render_gbuffer(const std::vector<MeshDraw>& draws, const Camera& camera, int width, int height,
                       const std::vector<std::string>& attributes) {
  check_attributes(attributes);
  if (draws.empty()) throw std::invalid_argument("a G-buffer needs at least one mesh");
  for (const auto& [m, model] : draws) {
    for (const auto& a : attributes) {
      if (a == "uv" && !m->has_uvs)
        throw std::invalid_argument("attribute 'uv': mesh '" + m->name + "' has no texture coordinates" +
                                    (m->uv_sets.empty() ? std::string() : " (" + m->uv_sets + ")") +
                                    "; choose inputs it has, e.g. \"normal\", \"view\", \"position\"");
      if (a == "base_color" && !m->base_color)
        throw std::invalid_argument("attribute 'base_color': mesh '" + m->name +
                                    "' has no base-colour texture (a textured model needs one, e.g. Duck.gltf)");
    }
  }
  gl::ProgramDesc desc;
  desc.vertex = "mesh.vert";
  desc.fragment = "gbuffer.frag";
  for (std::size_t i = 0; i < attributes.size(); ++i) desc.defines[define_name(attributes[i])] = std::to_string(i);
  auto prog = gl::get_program(desc);

  GBuffer g;
  g.target = gl::pooled_target(width, height, int(attributes.size()));
  g.attributes = attributes;
  g.width = width;
  g.height = height;
  g.target->clear_drawn();  // a reused target: only where its last G-buffer's meshes were
  g.target->bind();
  const double aspect = camera.aspect_for(width, height);
  const glm::dmat4 view_proj = camera.projection(aspect) * camera.view();
  g.bounded = true;
  g.covers = {width, height, 0, 0};
  for (const auto& [m, model] : draws) {
    GpuMesh& gpu = upload(*m);
    set_standard_uniforms(*prog, camera, aspect, model, gpu);
    draw(*prog, gpu, model, Cull::none);
    PixelBox b;
    if (!g.bounded || !projected_box(gpu.bounds(), view_proj * model, width, height, &b)) {
      g.bounded = false;
      continue;
    }
    if (b.width() <= 0 || b.height() <= 0) continue;  // off screen
    g.covers = {std::min(g.covers.x0, b.x0), std::min(g.covers.y0, b.y0), std::max(g.covers.x1, b.x1),
                std::max(g.covers.y1, b.y1)};
  }
  if (g.covers.x1 <= g.covers.x0 || g.covers.y1 <= g.covers.y0) g.covers = {0, 0, 0, 0};
  if (g.bounded) g.target->set_drawn({g.covers.x0, g.covers.y0, g.covers.x1, g.covers.y1});
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  ++g_renders;
  return g;
}

std::size_t gbuffer_renders() { return g_renders; }

}  // namespace sn::scene

#include "shading/lighting_gpu.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace sn::shading {

namespace {

constexpr unsigned kLocalSize = 64;  // local_size_x of both compute shaders
constexpr std::size_t kChunk = std::size_t(65535) * kLocalSize;  // samples per dispatch

// Runs `prog` over [0, count) in dispatches of at most kChunk samples (u_first, u_count).
void dispatch_samples(gl::Program& prog, std::size_t count) {
  for (std::size_t first = 0; first < count; first += kChunk) {
    std::size_t n = std::min(kChunk, count - first);
    prog.set_uniform("u_first", {double(first)});
    prog.set_uniform("u_count", {double(n)});
    gl::dispatch(prog, unsigned((n + kLocalSize - 1) / kLocalSize));
  }
}

void require_size(const gl::Buffer& b, std::size_t count, const char* what) {
  if (gl::elem_info(b.type()).components != 4 || b.count() < count)
    throw std::invalid_argument(std::string(what) + " buffer must be vec4 with at least " + std::to_string(count) +
                                " elements, got " + gl::elem_info(b.type()).name + " x " + std::to_string(b.count()));
}

std::vector<float> to_vec4(const std::vector<glm::vec3>& v) {
  std::vector<float> out(v.size() * 4, 1.0f);
  for (std::size_t i = 0; i < v.size(); ++i)
    for (int c = 0; c < 3; ++c) out[i * 4 + c] = v[i][c];
  return out;
}

std::vector<glm::vec3> from_vec4(const gl::Buffer& b, std::size_t count) {
  std::vector<float> f(count * 4);
  if (count) b.download(f.data(), 0, f.size());
  std::vector<glm::vec3> out(count);
  for (std::size_t i = 0; i < count; ++i) out[i] = {f[i * 4], f[i * 4 + 1], f[i * 4 + 2]};
  return out;
}

std::shared_ptr<gl::Buffer> upload(const std::vector<glm::vec3>& v) {
  auto b = std::make_shared<gl::Buffer>(gl::ElemType::vec4, std::max<std::size_t>(v.size(), 1));
  auto f = to_vec4(v);
  if (!f.empty()) b->upload(f.data(), 0, f.size());
  return b;
}

}  // namespace

gl::Defines lighting_defines(const LightingParams& p) { return {{"LIGHTING_MODEL", std::to_string(int(p.model))}}; }

void set_lighting_uniforms(gl::Program& prog, const LightingParams& p, const scene::Light& light) {
  if (!(std::abs(glm::length(light.dir) - 1.0) < 1e-6))  // float-rounded unit vectors pass
    throw std::logic_error("the light direction must be unit length (build lights with make_light)");
  prog.set_uniform("u_light_dir", {light.dir.x, light.dir.y, light.dir.z});
  if (prog.uniform("u_light_color"))  // toon3's colours are its own: it reads only the direction
    prog.set_uniform("u_light_color", {light.color.r, light.color.g, light.color.b});
  const ModelSpec& s = p.spec();
  for (std::size_t i = 0; i < s.params.size(); ++i) {
    std::string name = std::string("u_") + s.params[i].name;
    // A parameter the compiler found unused (e.g. base colours of a shader that never reads
    // them) has no location; every name comes from the spec table, so this hides no typo.
    if (!prog.uniform(name)) continue;
    prog.set_uniform(name, std::vector<double>(p.values[i].begin(), p.values[i].begin() + s.params[i].components));
  }
}

void evaluate(const LightingParams& p, const scene::Light& light, const gl::Buffer& normals, const gl::Buffer& views,
              const gl::Buffer* base_colors, gl::Buffer& targets, std::size_t count, shading::ColorSpace color, bool raw) {
  if (count == 0) return;
  require_size(normals, count, "normals");
  require_size(views, count, "views");
  require_size(targets, count, "targets");
  if (p.spec().textured) {
    if (!base_colors)
      throw std::invalid_argument(std::string("lighting model ") + p.spec().name + " needs base colours (a texture)");
    require_size(*base_colors, count, "base colour");
  }
  gl::Defines d = lighting_defines(p);
  d["COLOR_SPACE"] = std::to_string(int(color));
  d["LIGHTING_RAW"] = raw ? "1" : "0";
  gl::ProgramDesc desc;
  desc.compute = "eval_lighting.comp";
  desc.defines = d;
  auto prog = gl::get_program(desc);
  set_lighting_uniforms(*prog, p, light);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, normals.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, views.id());
  if (base_colors) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, base_colors->id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, targets.id());
  dispatch_samples(*prog, count);
}

std::vector<glm::vec3> evaluate(const LightingParams& p, const scene::Light& light, const std::vector<glm::vec3>& normals,
                                const std::vector<glm::vec3>& views, const std::vector<glm::vec3>& base_colors,
                                shading::ColorSpace color, bool raw) {
  if (normals.size() != views.size())
    throw std::invalid_argument("evaluate: " + std::to_string(normals.size()) + " normals but " +
                                std::to_string(views.size()) + " view directions");
  if (p.spec().textured && base_colors.size() != normals.size())
    throw std::invalid_argument("evaluate: a textured model needs one base colour per sample");
  std::size_t n = normals.size();
  auto nb = upload(normals), vb = upload(views);
  auto bb = p.spec().textured ? upload(base_colors) : nullptr;
  gl::Buffer out(gl::ElemType::vec4, std::max<std::size_t>(n, 1));
  evaluate(p, light, *nb, *vb, bb.get(), out, n, color, raw);
  return from_vec4(out, n);
}

void convert_colors(const gl::Buffer& in, gl::Buffer& out, std::size_t count, shading::ColorSpace space, bool to_rgb) {
  if (count == 0) return;
  require_size(in, count, "colour input");
  require_size(out, count, "colour output");
  gl::ProgramDesc desc;
  desc.compute = "convert_color.comp";
  desc.defines = {{"COLOR_SPACE", std::to_string(int(space))}, {"TO_RGB", to_rgb ? "1" : "0"}};
  auto prog = gl::get_program(desc);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, out.id());
  dispatch_samples(*prog, count);
}

std::vector<glm::vec3> convert_colors(const std::vector<glm::vec3>& in, shading::ColorSpace space, bool to_rgb) {
  auto ib = upload(in);
  gl::Buffer out(gl::ElemType::vec4, std::max<std::size_t>(in.size(), 1));
  convert_colors(*ib, out, in.size(), space, to_rgb);
  return from_vec4(out, in.size());
}

}  // namespace sn::shading

#include "shading/lighting_gpu.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cctype>
#include <regex>
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

namespace {

const char* glsl_type(int components) { return components == 1 ? "float" : components == 3 ? "vec3" : "vec4"; }

std::string upper(const std::string& s) {
  std::string u;
  for (char c : s) u += char(std::toupper(static_cast<unsigned char>(c)));
  return u;
}

// The name the definition's source is #included by: a built-in's file, or a definition's
// captured text.
std::string source_include(const LightingModel& m) { return m.glsl_path.empty() ? m.glsl_name : m.glsl_path; }

// A parameter's uniform: a prefix of its own, so that no parameter name (`view`, `position`,
// `count`) meets the uniforms of the shaders that include the model (u_view, u_count).
std::string param_uniform(const std::string& name) { return "u_param_" + name; }

// Binding of each surface attribute's buffer in eval_lighting.comp.
int attribute_binding(const std::string& a) {
  const auto& all = surface_attributes();
  return 3 + int(std::find(all.begin(), all.end(), a) - all.begin());
}

}  // namespace

gl::Includes lighting_includes(const LightingModel& m, const std::vector<std::string>& vary) {
  std::string g = "// Lighting model '" + m.name + "', assembled by runtime/shading/lighting_gpu.cpp.\n";
  g += "#include \"lighting/common.glsl\"\n#include \"lighting/surface.glsl\"\n";
  g += "struct Params {\n";
  for (const auto& ps : m.params) g += std::string("  ") + glsl_type(ps.components) + " " + ps.name + ";\n";
  if (m.params.empty()) g += "  float unused_;  // GLSL has no empty structs\n";
  g += "};\nuniform vec3 u_light_dir;  // unit, towards the light\nuniform vec3 u_light_color;\n";
  for (const auto& ps : m.params) g += std::string("uniform ") + glsl_type(ps.components) + " " + param_uniform(ps.name) + ";\n";
  g += "#include \"" + source_include(m) + "\"\n";
  g += "Params lighting_params() {\n  Params p;\n";
  for (const auto& ps : m.params) g += "  p." + ps.name + " = " + param_uniform(ps.name) + ";\n";
  if (m.params.empty()) g += "  p.unused_ = 0.0;\n";
  g += "  return p;\n}\n";
  if (!vary.empty()) {
    // Parameters a dataset varies per row arrive as the components of one vec4 per sample.
    g += "void lighting_vary(inout Params p, vec4 x) {\n";
    for (std::size_t k = 0; k < vary.size(); ++k) g += "  p." + vary[k] + " = x[" + std::to_string(k) + "];\n";
    g += "}\n";
  }
  g += "// n and v normalised, the light filled in; the caller sets the attributes the model reads.\n"
       "Surface lighting_surface(vec3 n, vec3 v) {\n"
       "  return Surface(safe_normalize(n), safe_normalize(v), u_light_dir, u_light_color, vec3(1.0), vec2(0.0),\n"
       "                 vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));\n}\n"
       "vec3 lighting_raw(Surface s, Params p) { return shade(s, p); }\n"
       "vec3 lighting(Surface s, Params p) { return clamp(shade(s, p), 0.0, 1.0); }\n"
       "vec3 lighting_raw(Surface s) { return shade(s, lighting_params()); }\n"
       "vec3 lighting(Surface s) { return clamp(lighting_raw(s), 0.0, 1.0); }\n";
  gl::Includes inc{{"lighting/model.glsl", g}};
  if (m.glsl_path.empty()) {
    inc[m.glsl_name] = m.glsl_source;
    inc.insert(m.glsl_includes.begin(), m.glsl_includes.end());
  }
  return inc;
}

void use_lighting(gl::ProgramDesc& desc, const LightingParams& p, const std::vector<std::string>& vary) {
  for (auto& [k, v] : lighting_includes(p.spec(), vary)) desc.includes[k] = v;
  if (!vary.empty()) desc.defines["LIGHTING_VARY"] = "1";
  for (const auto& a : p.spec().attributes) desc.defines["SURFACE_" + upper(a)] = "1";
}

void check_vary(const LightingModel& m, const std::vector<std::string>& vary) {
  if (vary.size() > 4) throw std::invalid_argument("a dataset varies at most 4 parameters per row, got " + std::to_string(vary.size()));
  for (std::size_t k = 0; k < vary.size(); ++k) {
    auto it = std::find_if(m.params.begin(), m.params.end(), [&](const ParamSpec& ps) { return ps.name == vary[k]; });
    if (it == m.params.end()) {
      std::string valid;
      for (const auto& ps : m.params) valid += (valid.empty() ? "" : ", ") + ps.name;
      throw std::invalid_argument("lighting model " + m.name + " has no parameter '" + vary[k] + "' to vary (valid: " + valid + ")");
    }
    if (it->components != 1)
      throw std::invalid_argument("lighting model " + m.name + " parameter '" + vary[k] +
                                  "' has " + std::to_string(it->components) + " components; only numbers can vary per row");
    if (std::find(vary.begin(), vary.begin() + long(k), vary[k]) != vary.begin() + long(k))
      throw std::invalid_argument("parameter '" + vary[k] + "' is varied twice");
  }
}

void set_lighting_uniforms(gl::Program& prog, const LightingParams& p, const scene::Light& light) {
  if (!(std::abs(glm::length(light.dir) - 1.0) < 1e-6))  // float-rounded unit vectors pass
    throw std::logic_error("the light direction must be unit length (build lights with make_light)");
  if (prog.uniform("u_light_dir")) prog.set_uniform("u_light_dir", {light.dir.x, light.dir.y, light.dir.z});
  if (prog.uniform("u_light_color"))  // toon3's colours are its own: it reads only the direction
    prog.set_uniform("u_light_color", {light.color.r, light.color.g, light.color.b});
  const LightingModel& s = p.spec();
  for (std::size_t i = 0; i < s.params.size(); ++i) {
    std::string name = param_uniform(s.params[i].name);
    // A parameter the compiler found unused has no location; every name comes from the
    // definition, so this hides no typo.
    if (!prog.uniform(name)) continue;
    prog.set_uniform(name, std::vector<double>(p.values[i].begin(), p.values[i].begin() + s.params[i].components));
  }
}

void compile_lighting(const LightingModel& m) {
  static const std::regex entry(R"(vec3\s+shade\s*\(\s*(in\s+)?Surface\s+\w+\s*,\s*(in\s+)?Params\s+\w+\s*\))");
  if (!std::regex_search(gl::without_glsl_comments(m.glsl_text()), entry))
    throw std::invalid_argument("lighting model '" + m.name + "': its glsl (" + gl::display_path(source_include(m)) +
                                ") must define vec3 shade(Surface s, Params p) (docs/lua-api/ground-truth.md)");
  gl::ProgramDesc desc;
  desc.compute = "eval_lighting.comp";
  desc.defines = {{"COLOR_SPACE", "0"}, {"LIGHTING_RAW", "1"}};
  LightingParams p;
  p.model = std::make_shared<const LightingModel>(m);
  use_lighting(desc, p);
  gl::NoProgramFallback strict;  // in live mode too: a broken definition is an error, not the last good one
  gl::get_program(desc);
}

void check_finite_targets(const LightingParams& p, const std::vector<float>& targets, std::size_t count,
                          const std::function<std::string(std::size_t)>& sample) {
  std::size_t bad = 0, first = 0;
  for (std::size_t i = 0; i < count; ++i)
    if (targets[i * 4 + 3] != 1.0f && bad++ == 0) first = i;
  if (bad == 0) return;
  throw std::runtime_error("lighting model '" + p.spec().name + "' gave NaN or infinite radiance for " +
                           std::to_string(bad) + " of " + std::to_string(count) + " samples (the first: " +
                           sample(first) + "); shade() must return finite values for every input, and " +
                           "sn.lighting.stress(model) shows where it does not");
}

void evaluate(const LightingParams& p, const scene::Light& light, const SampleBuffers& in, gl::Buffer& targets,
              std::size_t count, shading::ColorSpace color, bool raw, const Varied* varied) {
  if (count == 0) return;
  const LightingModel& m = p.spec();
  std::vector<std::string> vary;
  if (varied) {
    vary = varied->params;
    check_vary(m, vary);
    require_size(*varied->values, count, "varied parameter");
  }
  auto get = [&](const std::string& a) -> const gl::Buffer& {
    auto it = in.find(a);
    if (it == in.end() || !it->second)
      throw std::invalid_argument("lighting model " + m.name + " reads the attribute '" + a +
                                  "', which these samples do not hold");
    require_size(*it->second, count, (a + " samples").c_str());
    return *it->second;
  };
  const gl::Buffer& normals = get("normal");
  const gl::Buffer& views = get("view");
  require_size(targets, count, "targets");
  gl::ProgramDesc desc;
  desc.compute = "eval_lighting.comp";
  desc.defines = {{"COLOR_SPACE", std::to_string(int(color))}, {"LIGHTING_RAW", raw ? "1" : "0"}};
  use_lighting(desc, p, vary);
  auto prog = gl::get_program(desc);
  set_lighting_uniforms(*prog, p, light);
  if (varied) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 9, varied->values->id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, normals.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, views.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, targets.id());
  for (const auto& a : m.attributes) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, GLuint(attribute_binding(a)), get(a).id());
  dispatch_samples(*prog, count);
}

std::vector<glm::vec3> evaluate(const LightingParams& p, const scene::Light& light, const HostSamples& in,
                                shading::ColorSpace color, bool raw) {
  auto normals = in.find("normal");
  std::size_t n = normals == in.end() ? 0 : normals->second.size();
  std::vector<std::shared_ptr<gl::Buffer>> keep;
  SampleBuffers buffers;
  for (const auto& [a, v] : in) {
    if (v.size() != n)
      throw std::invalid_argument("evaluate: " + std::to_string(n) + " normals but " + std::to_string(v.size()) + " " + a +
                                  " samples");
    keep.push_back(upload(v));
    buffers[a] = keep.back().get();
  }
  gl::Buffer out(gl::ElemType::vec4, std::max<std::size_t>(n, 1));
  evaluate(p, light, buffers, out, n, color, raw);
  return from_vec4(out, n);
}

std::vector<glm::vec3> evaluate(const LightingParams& p, const scene::Light& light, const std::vector<glm::vec3>& normals,
                                const std::vector<glm::vec3>& views, const std::vector<glm::vec3>& base_colors,
                                shading::ColorSpace color, bool raw) {
  HostSamples in{{"normal", normals}, {"view", views}};
  if (p.spec().reads("base_color")) in["base_color"] = base_colors;
  return evaluate(p, light, in, color, raw);
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

#include "shading/lighting_model.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>

#include "gl/shader_source.h"
#include "io/limits.h"
#include "io/read_file.h"
#include "io/text.h"
#include "shading/builtin_models.h"
#include "shading/lighting.h"

namespace sn::shading {

namespace {

std::vector<ModelPtr>& table() {
  static std::vector<ModelPtr> t;
  return t;
}

void add(LightingModel m);

// The built-ins register through the same door as a user's definition, on first use.
void ensure_builtins() {
  static bool done = false;
  if (done) return;
  done = true;
  for (auto& m : builtin_models()) add(std::move(m));
}

bool identifier(const std::string& s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  for (char c : s)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
  return s.rfind("gl_", 0) != 0 && s.find("__") == std::string::npos;
}

void check_definition(const LightingModel& m) {
  std::string who = "lighting model '" + m.name + "'";
  if (!identifier(m.name))
    throw std::invalid_argument("lighting model name '" + m.name +
                                "' must be an identifier (letters, digits, _; not starting with a digit or gl_)");
  for (std::size_t i = 0; i < m.params.size(); ++i) {
    const ParamSpec& p = m.params[i];
    std::string where = who + " parameter '" + p.name + "'";
    if (!identifier(p.name) || p.name == "light_dir" || p.name == "light_color")
      throw std::invalid_argument(where + ": the name must be an identifier other than light_dir and light_color");
    if (gl::glsl_reserved_word(p.name))
      throw std::invalid_argument(where + ": the name is a GLSL keyword or type (the parameter is a field of the GLSL "
                                  "struct Params); choose another name");
    for (std::size_t j = 0; j < i; ++j)
      if (m.params[j].name == p.name) throw std::invalid_argument(where + " is listed twice");
    if (p.components != 1 && p.components != 3 && p.components != 4)
      throw std::invalid_argument(where + ": 1, 3 or 4 components, got " + std::to_string(p.components));
    if (!(std::isfinite(p.min) && std::isfinite(p.max) && p.min <= p.max))
      throw std::invalid_argument(where + ": the range must be finite with min <= max, got [" +
                                  io::number_text(p.min) + ", " + io::number_text(p.max) + "]");
    for (int c = 0; c < p.components; ++c)
      if (!(p.def[c] >= p.min && p.def[c] <= p.max))
        throw std::invalid_argument(where + ": the default " + io::number_text(p.def[c]) + " lies outside its range [" +
                                    io::number_text(p.min) + ", " + io::number_text(p.max) + "]");
  }
  const auto& valid = surface_attributes();
  for (std::size_t i = 0; i < m.attributes.size(); ++i) {
    const auto& a = m.attributes[i];
    if (std::find(valid.begin(), valid.end(), a) == valid.end()) {
      std::string list;
      for (const auto& v : valid) list += (list.empty() ? "" : ", ") + v;
      throw std::invalid_argument(who + ": unknown attribute '" + a + "' (valid: " + list +
                                  "; normal and view are always given)");
    }
    if (std::find(m.attributes.begin(), m.attributes.begin() + long(i), a) != m.attributes.begin() + long(i))
      throw std::invalid_argument(who + ": attribute '" + a + "' is listed twice");
  }
  if (m.glsl_path.empty() && m.glsl_source.empty()) throw std::invalid_argument(who + ": no glsl (a file or source)");
  if (!m.twin) throw std::invalid_argument(who + ": no twin");
}

void add(LightingModel m) {
  check_definition(m);
  auto& t = table();
  auto it = std::find_if(t.begin(), t.end(), [&](const ModelPtr& p) { return p->name == m.name; });
  if (it != t.end() && (*it)->builtin)
    throw std::invalid_argument("lighting model '" + m.name + "' would shadow the built-in model of that name; choose another name");
  auto p = std::make_shared<const LightingModel>(std::move(m));
  if (it != t.end()) *it = p;
  else t.push_back(p);
}

}  // namespace

bool LightingModel::reads(const std::string& attribute) const {
  return std::find(attributes.begin(), attributes.end(), attribute) != attributes.end();
}

std::string LightingModel::glsl_text() const {
  if (glsl_path.empty()) return glsl_source;
  return io::read_file(glsl_path, "the glsl file of lighting model '" + name + "'", io::limits().shader_bytes,
                       "shader_bytes");
}

bool LightingModel::same_glsl(const LightingModel& o) const {
  return glsl_path == o.glsl_path && glsl_source == o.glsl_source && glsl_name == o.glsl_name &&
         glsl_includes == o.glsl_includes;
}

void validate_model(const LightingModel& m) {
  ensure_builtins();
  check_definition(m);
  for (const auto& p : table())
    if (p->name == m.name && p->builtin)
      throw std::invalid_argument("lighting model '" + m.name + "' would shadow the built-in model of that name; choose another name");
}

void register_model(LightingModel m) {
  ensure_builtins();
  m.builtin = false;
  add(std::move(m));
}

ModelPtr find_model(const std::string& name) {
  ensure_builtins();
  for (const auto& m : table())
    if (m->name == name) return m;
  throw std::invalid_argument("unknown lighting model '" + name + "' (valid: " + model_names() + ")");
}

std::vector<ModelPtr> models() {
  ensure_builtins();
  return table();
}

std::string model_names() {
  ensure_builtins();
  std::string s;
  for (const auto& m : table()) s += (s.empty() ? "" : ", ") + m->name;
  return s;
}

const std::vector<std::string>& surface_attributes() {
  static const std::vector<std::string> a = {"base_color", "uv", "position", "world_position", "tangent", "bitangent"};
  return a;
}

Surface make_surface(const scene::Light& light, const glm::dvec3& n, const glm::dvec3& v) {
  Surface s;
  s.n = safe_normalize(n);
  s.v = safe_normalize(v);
  s.l = light.dir;
  s.light_color = light.color;
  return s;
}

}  // namespace sn::shading

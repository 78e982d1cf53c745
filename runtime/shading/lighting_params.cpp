#include "shading/lighting_params.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "io/text.h"

namespace sn::shading {

namespace {

constexpr double kColorMax = 1e3;  // colours and weights: finite, so every model's output has a bound
constexpr double kExponentMax = 1e6;

// The Phong reflectance the thesis writes (section 2.2): C_p [cos(i)(1 - d) + d] + W cos(s)^n.
std::vector<ParamSpec> phong_params(double shininess, std::array<double, 4> color, double ambient,
                                    double specular) {
  return {
      {"color", 3, color, 0, kColorMax, "C_p, the diffuse reflection coefficient (r, g, b)"},
      {"ambient", 1, {ambient}, 0, 1, "d, the share of environmental (ambient) reflection, 0..1"},
      {"specular", 3, {specular, specular, specular}, 0, kColorMax, "W, the specular reflection ratio (r, g, b)"},
      {"shininess", 1, {shininess}, 0, kExponentMax, "n, the specular exponent"},
  };
}

std::vector<ModelSpec> build_specs() {
  return {
      {Model::phong, "phong", phong_params(32, {0.8, 0.8, 0.8}, 0.1, 0.5), false},
      // Blinn's n.h lobe is about 4x wider than Phong's r.v lobe at the same exponent.
      {Model::blinn_phong, "blinn_phong", phong_params(128, {0.8, 0.8, 0.8}, 0.1, 0.5), false},
      {Model::ggx,
       "ggx",
       {
           {"roughness", 1, {0.3}, 0, 1, "perceptual roughness r; the GGX width is alpha = r^2 (at least 1e-3)"},
           {"f0", 3, {1.0, 0.71, 0.29}, 0, 1, "F0, Fresnel reflectance at normal incidence (r, g, b); gold by default"},
           {"diffuse", 3, {0, 0, 0}, 0, 1, "Lambertian albedo (r, g, b); 0 for metals"},
           {"ambient", 3, {0.1, 0.1, 0.1}, 0, kColorMax, "ambient light (r, g, b), reflected with albedo diffuse + f0"},
       },
       false},
      {Model::toon3,
       "toon3",
       {
           {"ambient", 3, {0.12, 0.1, 0.3}, 0, kColorMax, "C_a, colour where the Phong reflectance is lowest"},
           {"diffuse", 3, {0.85, 0.35, 0.2}, 0, kColorMax, "C_d, colour of the lit middle band"},
           {"specular", 3, {1.0, 0.95, 0.7}, 0, kColorMax, "C_s, colour of the highlight"},
           {"a", 1, {0.5}, 0, 1, "blend factor of the two transition bands"},
           {"thresholds", 4, {0.3, 0.4, 0.9, 1.0}, 0, kExponentMax, "t1 <= t2 <= t3 <= t4 on the Phong reflectance S_p"},
           {"shininess", 1, {32}, 0, kExponentMax, "n of the Phong reflectance S_p"},
           {"ambient_weight", 1, {0.1}, 0, 1, "d of the Phong reflectance S_p"},
           {"specular_weight", 1, {0.5}, 0, kColorMax, "W of the Phong reflectance S_p"},
       },
       false},
      {Model::textured_phong, "textured_phong", phong_params(32, {1, 1, 1}, 0.2, 0.3), true},
  };
}

std::string values_text(const std::array<double, 4>& v, int n) {
  if (n == 1) return io::number_text(v[0]);
  std::string s = "{";
  for (int i = 0; i < n; ++i) s += (i ? ", " : "") + io::number_text(v[i]);
  return s + "}";
}

}  // namespace

const std::vector<ModelSpec>& model_specs() {
  static const std::vector<ModelSpec> specs = build_specs();
  return specs;
}

const ModelSpec& model_spec(Model m) { return model_specs().at(size_t(m)); }

std::string model_names() {
  std::string s;
  for (const auto& m : model_specs()) s += (s.empty() ? "" : ", ") + std::string(m.name);
  return s;
}

const ModelSpec& model_spec(const std::string& name) {
  for (const auto& m : model_specs())
    if (name == m.name) return m;
  throw std::invalid_argument("unknown lighting model '" + name + "' (valid: " + model_names() + ")");
}

namespace {
size_t param_index(const ModelSpec& s, const char* name) {
  for (size_t i = 0; i < s.params.size(); ++i)
    if (std::string(name) == s.params[i].name) return i;
  throw std::logic_error(std::string("lighting model ") + s.name + " has no parameter '" + name + "'");
}
}  // namespace

double LightingParams::scalar(const char* name) const { return values[param_index(spec(), name)][0]; }

glm::dvec3 LightingParams::color(const char* name) const {
  const auto& v = values[param_index(spec(), name)];
  return {v[0], v[1], v[2]};
}

glm::dvec4 LightingParams::vec4(const char* name) const {
  const auto& v = values[param_index(spec(), name)];
  return {v[0], v[1], v[2], v[3]};
}

std::string LightingParams::describe() const {
  const auto& s = spec();
  std::string out = std::string(s.name) + "(";
  for (size_t i = 0; i < s.params.size(); ++i)
    out += (i ? ", " : "") + std::string(s.params[i].name) + "=" + values_text(values[i], s.params[i].components);
  return out + ")";
}

std::string LightingParams::key() const {
  const auto& s = spec();
  std::string out = s.name;
  for (size_t i = 0; i < s.params.size(); ++i) {
    out += std::string(" ") + s.params[i].name + "=";
    for (int c = 0; c < s.params[i].components; ++c) out += (c ? "," : "") + io::exact_text(values[i][c]);
  }
  return out;
}

LightingParams make_params(Model m, const std::map<std::string, std::vector<double>>& given) {
  const ModelSpec& s = model_spec(m);
  LightingParams p;
  p.model = m;
  for (const auto& ps : s.params) p.values.push_back(ps.def);
  for (const auto& [name, v] : given) {
    size_t i = 0;
    while (i < s.params.size() && name != s.params[i].name) ++i;
    if (i == s.params.size()) {
      std::string valid;
      for (const auto& ps : s.params) valid += (valid.empty() ? "" : ", ") + std::string(ps.name);
      throw std::invalid_argument(std::string("sn.lighting.") + s.name + ": unknown parameter '" + name +
                                  "' (valid: " + valid + ")");
    }
    const ParamSpec& ps = s.params[i];
    std::string where = std::string("sn.lighting.") + s.name + " parameter '" + name + "'";
    std::array<double, 4> val{};
    if (v.size() == 1 && ps.components == 3) {
      val = {v[0], v[0], v[0], 0};  // a grey
    } else if (int(v.size()) == ps.components) {
      for (size_t c = 0; c < v.size(); ++c) val[c] = v[c];
    } else {
      throw std::invalid_argument(where + ": " + std::to_string(ps.components) +
                                  (ps.components == 3 ? " numbers {r, g, b} or 1 number" : " number(s)") +
                                  " expected, got " + std::to_string(v.size()));
    }
    for (int c = 0; c < ps.components; ++c) {
      if (!std::isfinite(val[c]) || val[c] < ps.min || val[c] > ps.max)
        throw std::invalid_argument(where + " (" + ps.meaning + ") must lie in [" + io::number_text(ps.min) + ", " +
                                    io::number_text(ps.max) + "], got " + values_text(val, ps.components));
    }
    p.values[i] = val;
  }
  if (m == Model::toon3) {
    glm::dvec4 t = p.vec4("thresholds");
    if (!(t[0] <= t[1] && t[1] <= t[2] && t[2] <= t[3]))
      throw std::invalid_argument("sn.lighting.toon3 parameter 'thresholds' must be in order t1 <= t2 <= t3 <= t4, got " +
                                  values_text(p.values[param_index(s, "thresholds")], 4));
  }
  return p;
}

}  // namespace sn::shading

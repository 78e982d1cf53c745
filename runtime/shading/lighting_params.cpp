#include "shading/lighting_params.h"

#include <cmath>
#include <stdexcept>

#include "io/text.h"

namespace sn::shading {

std::string values_text(const std::array<double, 4>& v, int n) {
  if (n == 1) return io::number_text(v[0]);
  std::string s = "{";
  for (int i = 0; i < n; ++i) s += (i ? ", " : "") + io::number_text(v[i]);
  return s + "}";
}

namespace {
size_t param_index(const LightingModel& s, const char* name) {
  for (size_t i = 0; i < s.params.size(); ++i)
    if (name == s.params[i].name) return i;
  throw std::logic_error("lighting model " + s.name + " has no parameter '" + name + "'");
}
}  // namespace

const LightingModel& LightingParams::spec() const {
  if (!model) throw std::logic_error("a lighting value without a model (use make_params)");
  return *model;
}

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
  std::string out = s.name + "(";
  for (size_t i = 0; i < s.params.size(); ++i)
    out += (i ? ", " : "") + s.params[i].name + "=" + values_text(values[i], s.params[i].components);
  return out + ")";
}

std::string LightingParams::key() const {
  const auto& s = spec();
  std::string out = s.name;
  for (size_t i = 0; i < s.params.size(); ++i) {
    out += " " + s.params[i].name + "=";
    for (int c = 0; c < s.params[i].components; ++c) out += (c ? "," : "") + io::exact_text(values[i][c]);
  }
  return out;
}

LightingParams make_params(const ModelPtr& m, const std::map<std::string, std::vector<double>>& given) {
  const LightingModel& s = *m;
  LightingParams p;
  p.model = m;
  for (const auto& ps : s.params) p.values.push_back(ps.def);
  for (const auto& [name, v] : given) {
    size_t i = 0;
    while (i < s.params.size() && name != s.params[i].name) ++i;
    if (i == s.params.size()) {
      std::string valid;
      for (const auto& ps : s.params) valid += (valid.empty() ? "" : ", ") + ps.name;
      throw std::invalid_argument("sn.lighting." + s.name + ": unknown parameter '" + name + "' (valid: " +
                                  (valid.empty() ? "none" : valid) + ")");
    }
    const ParamSpec& ps = s.params[i];
    std::string where = "sn.lighting." + s.name + " parameter '" + name + "'";
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
  if (s.check_values) s.check_values(p);
  return p;
}

}  // namespace sn::shading

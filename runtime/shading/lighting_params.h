// A lighting model with every parameter set: the value a Lua "Lighting" object holds, and what
// datasets, truth images and the stress test are built from. Parameters come from the model's
// definition (lighting_model.h); values are checked against each parameter's domain.
#pragma once
#include <array>
#include <map>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "shading/lighting_model.h"

namespace sn::shading {

struct LightingParams {
  ModelPtr model;
  std::vector<std::array<double, 4>> values;  // one per model->params, same order

  const LightingModel& spec() const;  // throws for a default-constructed (model-less) value
  double scalar(const char* name) const;
  glm::dvec3 color(const char* name) const;
  glm::dvec4 vec4(const char* name) const;
  // "ggx(roughness=0.3, f0={1, 0.71, 0.29}, diffuse={0, 0, 0}, ambient={0.05, 0.05, 0.05})"
  std::string describe() const;
  // Exact text of every value (hex floats), for cache keys. The model's GLSL is keyed by the
  // caches themselves (they hash the shader sources a value passes through).
  std::string key() const;
};

// Builds a model from named values; each vector holds 1 number, or `components` numbers.
// Throws naming the model and parameter for an unknown name (listing the valid ones), a wrong
// number of values, a value outside its domain, or a failed cross-parameter check.
LightingParams make_params(const ModelPtr& m, const std::map<std::string, std::vector<double>>& given);
inline LightingParams make_params(const std::string& name, const std::map<std::string, std::vector<double>>& given) {
  return make_params(find_model(name), given);
}
inline LightingParams default_params(const std::string& name) { return make_params(name, {}); }

// "0.3" or "{1, 0.71, 0.29}": a parameter value as errors and describe() write it.
std::string values_text(const std::array<double, 4>& v, int n);

}  // namespace sn::shading

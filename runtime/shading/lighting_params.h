// The lighting models a scene can be shaded with, their parameters, and each parameter's
// domain. One table (model_specs) drives the Lua constructors, validation, the GLSL uniforms
// ("u_" + name), the CPU twin and the dataset cache key, so a parameter exists in one place.
#pragma once
#include <array>
#include <map>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace sn::shading {

// The order is the value of LIGHTING_MODEL in shaders/include/lighting/model.glsl.
enum class Model { phong, blinn_phong, ggx, toon3, textured_phong };

struct ParamSpec {
  const char* name;
  int components;             // 1 scalar, 3 colour (a single number is spread over r, g, b), 4 thresholds
  std::array<double, 4> def;  // default (first `components` used)
  double min, max;            // every component must lie in [min, max]
  const char* meaning;        // one line for error messages and docs
};

struct ModelSpec {
  Model model;
  const char* name;  // "phong", "blinn_phong", "ggx", "toon3", "textured_phong"
  std::vector<ParamSpec> params;
  bool textured;  // reads the mesh's base colour (G-buffer attribute "base_color")
};

const std::vector<ModelSpec>& model_specs();
const ModelSpec& model_spec(Model m);
// Throws "unknown lighting model 'x' (valid: phong, blinn_phong, ggx, toon3, textured_phong)".
const ModelSpec& model_spec(const std::string& name);
std::string model_names();  // "phong, blinn_phong, ..."

// One model with every parameter set (defaults where not given), validated.
struct LightingParams {
  Model model = Model::phong;
  std::vector<std::array<double, 4>> values;  // one per model_spec(model).params, same order

  const ModelSpec& spec() const { return model_spec(model); }
  double scalar(const char* name) const;
  glm::dvec3 color(const char* name) const;
  glm::dvec4 vec4(const char* name) const;
  // "ggx(roughness=0.3, f0={1, 0.71, 0.29}, diffuse={0, 0, 0}, ambient={0.05, 0.05, 0.05})"
  std::string describe() const;
  // Exact text of every value (hex floats), for cache keys.
  std::string key() const;
};

// Builds a model from named values; each vector holds 1 number, or `components` numbers.
// Throws naming the model and parameter for an unknown name (listing the valid ones), a wrong
// number of values, a value outside its domain, or thresholds out of order.
LightingParams make_params(Model m, const std::map<std::string, std::vector<double>>& given);
inline LightingParams default_params(Model m) { return make_params(m, {}); }

}  // namespace sn::shading

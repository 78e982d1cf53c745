// The registry of lighting models. A model is a definition: its parameters and their domains,
// the G-buffer attributes it reads, one GLSL function that shades a surface point, and a
// double-precision twin of that function. The five built-ins (builtin_models.cpp) and a user's
// sn.lighting.define{...} register the same way and are used the same way everywhere: datasets,
// truth images, the stress test, check(), live mode.
//
// The GLSL function a definition gives (file or string) is
//   vec3 shade(Surface s, Params p)
// returning linear RGB radiance, finite and >= 0 for any input. `Surface` is declared in
// shaders/include/lighting/surface.glsl; `Params` is generated from the parameter list (a float,
// vec3 or vec4 field per parameter, named as the parameter). Docs: docs/lua-api/ground-truth.md.
#pragma once
#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gl/shader_source.h"
#include "scene/light.h"

namespace sn::shading {

struct ParamSpec {
  std::string name;
  int components;             // 1 scalar, 3 colour (a single number is spread over r, g, b), 4 a vec4
  std::array<double, 4> def;  // default (first `components` used)
  double min, max;            // every component must lie in [min, max]
  std::string meaning;        // one line for error messages and docs
};

// One surface point as the shading function sees it (the twin of GLSL's Surface): n, v and the
// tangent frame unit or zero, world space.
struct Surface {
  glm::dvec3 n{0.0}, v{0.0}, l{0.0, 1.0, 0.0};  // normal, towards the eye, towards the light
  glm::dvec3 light_color{1.0};
  glm::dvec3 base_color{1.0};  // the texture colour (models that read "base_color")
  glm::dvec2 uv{0.0};
  glm::dvec3 position{0.0}, world_position{0.0};
  glm::dvec3 tangent{0.0}, bitangent{0.0};
};

struct LightingParams;

struct LightingModel {
  std::string name;
  std::vector<ParamSpec> params;
  // G-buffer attributes read beyond "normal" and "view" (the only ones every model gets):
  // "base_color", "uv", "position", "world_position", "tangent", "bitangent".
  std::vector<std::string> attributes;
  // The GLSL. A built-in's is a file of the runtime (glsl_path, absolute), read when a program is
  // built like every shader of shadenet's. A user's definition is fixed when it is defined
  // (gl::capture_source): the text glsl_source, shown in errors as glsl_name (its file's path, or
  // "script.lua:LINE (glsl of NAME)"), and the files it #includes in glsl_includes; editing those
  // files afterwards changes no model already defined (defining it again reads them anew).
  std::string glsl_path, glsl_source, glsl_name;
  gl::Includes glsl_includes;
  // shade() in double precision; n, v, tangent and bitangent arrive normalised (or zero).
  std::function<glm::dvec3(const Surface&, const LightingParams&)> twin;
  // Optional: a per-channel bound on the raw radiance (the stress test counts values above it).
  std::function<glm::dvec3(const LightingParams&, const scene::Light&)> bound;
  // Optional: a check across parameters beyond each one's range (throws with the message).
  std::function<void(const LightingParams&)> check_values;
  // Optional: true where float and double may take different branches (toon3's thresholds);
  // n.l = 0, n.v = 0 and v = -l are always treated as such.
  std::function<bool(const LightingParams&, const Surface&, double eps)> near_branch;
  bool builtin = false;

  bool reads(const std::string& attribute) const;
  std::string glsl_text() const;  // a built-in's file (read now) or the captured source
  bool same_glsl(const LightingModel& o) const;  // the same GLSL, #included files and all
};

using ModelPtr = std::shared_ptr<const LightingModel>;

// Checks a definition (name, parameter schema and defaults, attributes, that a twin exists)
// and adds it; a user's definition may replace an earlier user definition of the same name
// (a re-run script), never a built-in. Throws naming the definition and the item.
void register_model(LightingModel m);
// The checks register_model makes, without registering.
void validate_model(const LightingModel& m);
// Throws "unknown lighting model 'x' (valid: phong, blinn_phong, ...)".
ModelPtr find_model(const std::string& name);
std::vector<ModelPtr> models();  // built-ins first, then user definitions in definition order
std::string model_names();       // "phong, blinn_phong, ..."

// The attributes a shading function may read beyond normal and view.
const std::vector<std::string>& surface_attributes();

// n, v (and tangent, bitangent) normalised as the shaders do, the light from `light`.
Surface make_surface(const scene::Light& light, const glm::dvec3& n, const glm::dvec3& v);

}  // namespace sn::shading

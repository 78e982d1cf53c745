// Lighting models and colour conversions on the GPU: shaders/eval_lighting.comp and
// shaders/convert_color.comp over sample buffers (vec4 per sample, .xyz used).
#pragma once
#include <cstddef>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gl/buffer.h"
#include "gl/program.h"
#include "scene/light.h"
#include "shading/color.h"
#include "shading/lighting_params.h"

namespace sn::shading {

// Makes a program shade with the model: "lighting/model.glsl" assembled from its definition
// (Params, the uniforms, its shade() function, lighting_surface/lighting_raw/lighting) and
// SURFACE_<ATTRIBUTE> defined for each attribute it reads.
// With `vary`, LIGHTING_VARY is defined and lighting_vary(inout Params, vec4) sets those
// parameters from a vec4 per sample.
void use_lighting(gl::ProgramDesc& desc, const LightingParams& p, const std::vector<std::string>& vary = {});
// The assembled "lighting/model.glsl" (and the definition's source when it is a string).
gl::Includes lighting_includes(const LightingModel& m, const std::vector<std::string>& vary = {});
// Throws unless `vary` names at most 4 distinct scalar parameters of the model.
void check_vary(const LightingModel& m, const std::vector<std::string>& vary);
// Sets u_light_dir, u_light_color and u_param_NAME of every parameter the program uses.
void set_lighting_uniforms(gl::Program& prog, const LightingParams& p, const scene::Light& light);
// Compiles the model's GLSL once (a small compute program), so a definition's error shows at
// its own file:line before any dataset is built.
void compile_lighting(const LightingModel& m);

// Per-sample vec4 buffers by G-buffer attribute: "normal" and "view", plus each attribute the
// model reads ("base_color", "uv", "tangent", ...).
using SampleBuffers = std::map<std::string, const gl::Buffer*>;

// Parameters that take a value per sample (a conditioned dataset): values[i][k] is params[k]
// at sample i (vec4 buffer).
struct Varied {
  std::vector<std::string> params;
  const gl::Buffer* values = nullptr;
};

// Shades `count` samples: targets[i] = the model at sample i in colour space `color`, or the
// unclamped RGB radiance when `raw`. Without `raw`, targets[i].w is 1, or 0 where the radiance
// was NaN or infinite (check_finite_targets). Throws naming an attribute the model reads that
// `in` lacks.
void evaluate(const LightingParams& p, const scene::Light& light, const SampleBuffers& in, gl::Buffer& targets,
              std::size_t count, shading::ColorSpace color = shading::ColorSpace::rgb, bool raw = false,
              const Varied* varied = nullptr);

// Throws when evaluate flagged a sample (w = 0) in `targets` (count vec4s, downloaded): the
// model's GLSL gave NaN or infinite radiance there. `sample(i)` describes sample i for the message.
void check_finite_targets(const LightingParams& p, const std::vector<float>& targets, std::size_t count,
                          const std::function<std::string(std::size_t)>& sample);

// Host-side convenience (uploads, evaluates, downloads): per attribute, one vec3 per sample
// (uv in .xy).
using HostSamples = std::map<std::string, std::vector<glm::vec3>>;
std::vector<glm::vec3> evaluate(const LightingParams& p, const scene::Light& light, const HostSamples& in,
                                shading::ColorSpace color = shading::ColorSpace::rgb, bool raw = false);
// The same for models that read normal, view and base_color at most.
std::vector<glm::vec3> evaluate(const LightingParams& p, const scene::Light& light, const std::vector<glm::vec3>& normals,
                                const std::vector<glm::vec3>& views, const std::vector<glm::vec3>& base_colors = {},
                                shading::ColorSpace color = shading::ColorSpace::rgb, bool raw = false);

// RGB -> `space` (to_rgb = false) or `space` -> RGB (to_rgb = true), on the GPU.
void convert_colors(const gl::Buffer& in, gl::Buffer& out, std::size_t count, shading::ColorSpace space, bool to_rgb);
std::vector<glm::vec3> convert_colors(const std::vector<glm::vec3>& in, shading::ColorSpace space, bool to_rgb);

}  // namespace sn::shading

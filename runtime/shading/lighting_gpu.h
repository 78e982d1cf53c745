// Lighting models and colour conversions on the GPU: shaders/eval_lighting.comp and
// shaders/convert_color.comp over sample buffers (vec4 per sample, .xyz used).
#pragma once
#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "gl/buffer.h"
#include "gl/program.h"
#include "scene/light.h"
#include "shading/color.h"
#include "shading/lighting_params.h"

namespace sn::shading {

// LIGHTING_MODEL for shaders/include/lighting/model.glsl.
gl::Defines lighting_defines(const LightingParams& p);
// Sets u_light_dir, u_light_color and "u_" + every parameter the program uses.
void set_lighting_uniforms(gl::Program& prog, const LightingParams& p, const scene::Light& light);

// Shades `count` samples: targets[i] = the model at (normals[i], views[i], base_colors[i]) in
// colour space `color`, or the unclamped RGB radiance when `raw`. `base_colors` is read only by
// textured models (may be null otherwise; throws when a textured model gets none).
void evaluate(const LightingParams& p, const scene::Light& light, const gl::Buffer& normals, const gl::Buffer& views,
              const gl::Buffer* base_colors, gl::Buffer& targets, std::size_t count,
              shading::ColorSpace color = shading::ColorSpace::rgb, bool raw = false);

// Host-side convenience (uploads, evaluates, downloads).
std::vector<glm::vec3> evaluate(const LightingParams& p, const scene::Light& light, const std::vector<glm::vec3>& normals,
                                const std::vector<glm::vec3>& views, const std::vector<glm::vec3>& base_colors = {},
                                shading::ColorSpace color = shading::ColorSpace::rgb, bool raw = false);

// RGB -> `space` (to_rgb = false) or `space` -> RGB (to_rgb = true), on the GPU.
void convert_colors(const gl::Buffer& in, gl::Buffer& out, std::size_t count, shading::ColorSpace space, bool to_rgb);
std::vector<glm::vec3> convert_colors(const std::vector<glm::vec3>& in, shading::ColorSpace space, bool to_rgb);

}  // namespace sn::shading

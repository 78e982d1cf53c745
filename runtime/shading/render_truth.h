// Ground-truth images: a lighting model evaluated at every covered pixel of a G-buffer by a
// fullscreen pass (shaders/shade_truth.frag), the same GLSL as the datasets' targets.
#pragma once
#include <string>
#include <vector>

#include "io/image.h"
#include "scene/gbuffer.h"
#include "scene/light.h"
#include "shading/lighting_params.h"

namespace sn::shading {

// The G-buffer attributes a model reads: {"normal", "view"} (+ "base_color" when textured).
std::vector<std::string> model_attributes(const LightingParams& p);

// RGBA image (alpha = coverage, colour clamped to [0, 1], background 0). Throws naming the
// missing attribute when `g` lacks one the model reads.
io::Image render_truth(const scene::GBuffer& g, const LightingParams& p, const scene::Light& light);

}  // namespace sn::shading

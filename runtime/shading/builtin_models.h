// The lighting models shadenet ships, as definitions for the registry (lighting_model.h): the
// GLSL in shaders/models/, the double twins in lighting.h.
#pragma once
#include <vector>

#include "shading/lighting_model.h"

namespace sn::shading {

std::vector<LightingModel> builtin_models();

}  // namespace sn::shading

// How glTF 2.0 moves a primitive's vertices before its node places it, as the loader draws them
// without animation: morph targets at their default weights (3.7.2.2). Run once, at load
// (scene/gltf.cpp).
#pragma once
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/gltf_accessor.h"

namespace sn::scene {

// Adds sum_i weights[i] * target_i to `pos` (3 per vertex) and, when `nrm` is not empty and a
// target has NORMAL, to `nrm`; TANGENT displacements are not read (tangents are generated or
// taken from the base). Targets past the end of `weights` weigh 0 (glTF's default). Throws naming
// the target when its accessor does not match the primitive's vertex count.
void add_morph_targets(const AccessorReader& reader, const tinygltf::Primitive& prim,
                       const std::vector<double>& weights, const std::string& what, const std::string& path,
                       std::vector<double>& pos, std::vector<double>& nrm);

}  // namespace sn::scene

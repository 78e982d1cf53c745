// The two ways glTF 2.0 moves a primitive's vertices before its node places it, as the loader
// draws them without animation: morph targets at their default weights (3.7.2.2) and skinning in
// the pose the file's joint nodes hold (3.7.3). Both run once, at load (scene/gltf.cpp).
#pragma once
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/gltf_accessor.h"

namespace sn::scene {

// Adds sum_i weights[i] * target_i to `pos` (3 per vertex) and, where they are not empty and a
// target has NORMAL or TANGENT, to `nrm` (3 per vertex) and `tan` (4 per vertex: its xyz; w, the
// handedness, stays). Targets past the end of `weights` weigh 0 (glTF's default). Throws naming
// the target when its accessor does not match the primitive's vertex count.
void add_morph_targets(const AccessorReader& reader, const tinygltf::Primitive& prim,
                       const std::vector<double>& weights, const std::string& what, const std::string& path,
                       std::vector<double>& pos, std::vector<double>& nrm, std::vector<double>& tan);

// One skin matrix per vertex: sum_i w_i * global(joint_i) * inverseBind_i over every JOINTS_n /
// WEIGHTS_n set of the primitive (linear blend skinning), `globals` holding each node's world
// transform. Weights are scaled to sum to 1; a vertex whose weights are all zero keeps the
// identity and is counted in `unweighted`. Throws for a missing JOINTS_0 / WEIGHTS_0, a joint
// index outside the skin, or a skin naming a node or matrix that is not there.
std::vector<glm::dmat4> skin_matrices(const AccessorReader& reader, const tinygltf::Model& model, int skin,
                                      const tinygltf::Primitive& prim, const std::vector<glm::dmat4>& globals,
                                      std::size_t count, const std::string& what, const std::string& path,
                                      std::size_t& unweighted);

// Moves each vertex through its skin matrix: positions (3 per vertex), normals (3, when not empty)
// through its inverse transpose, tangents (4, when not empty) through its linear part, their
// handedness flipped where it mirrors. Returns, per vertex, whether its matrix mirrors (the
// loader turns those triangles' winding).
std::vector<char> apply_skin(const std::vector<glm::dmat4>& skins, std::vector<double>& pos,
                             std::vector<double>& nrm, std::vector<double>& tan);

}  // namespace sn::scene

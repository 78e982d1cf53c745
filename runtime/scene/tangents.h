// Tangent frames for the G-buffer's "tangent" and "bitangent" (anisotropic lighting models).
// A tangent is a unit vector perpendicular to the vertex normal with a handedness w = +-1:
// bitangent = w cross(normal, tangent). Where they come from, in order of preference:
//   1. the glTF TANGENT attribute (Mesh::tangents, tangent_source "file");
//   2. analytic for procedural meshes (sphere, torus, plane: the direction of increasing u);
//   3. the mesh's UVs: per triangle the direction in which u grows (Lengyel's method), summed at
//      each vertex and orthonormalised against its normal, w from the direction v grows;
//   4. a fallback frame where there are no UVs or they are degenerate at a vertex: +X projected
//      onto the tangent plane (+Z where the normal is within about 2.6 degrees of +-X), w = +1.
#pragma once
#include <vector>

#include <glm/glm.hpp>

#include "scene/mesh.h"

namespace sn::scene {

// The fallback frame's tangent for a unit normal (w = +1).
glm::vec4 fallback_tangent(const glm::vec3& n);

// Tangents from the UVs (3, with 4 where a vertex's are degenerate); all fallback when the mesh
// has no UVs. One per vertex.
std::vector<glm::vec4> uv_tangents(const Mesh& m);

// m.tangents when the mesh has them, else uv_tangents(m).
std::vector<glm::vec4> mesh_tangents(const Mesh& m);

}  // namespace sn::scene

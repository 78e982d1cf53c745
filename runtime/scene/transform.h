// Placing meshes: 4x4 affine transforms (world = M * object), checked, and built from the
// rotate / scale / translate terms a script writes.
#pragma once
#include <optional>
#include <string>

#include <glm/glm.hpp>

namespace sn::scene {

// Whether every entry of m is a finite number.
bool is_finite(const glm::dmat4& m);

// Throws naming `what` unless m is finite, affine (last row 0 0 0 1) and invertible.
void check_transform(const glm::dmat4& m, const std::string& what);

// x -> about + T + R * S * (x - about): scale, then rotate (degrees about `axis`, right-handed),
// both about the point `about`, then translate. Throws for a zero axis or a zero scale.
struct TransformTerms {
  double degrees = 0;
  glm::dvec3 axis{0, 1, 0};
  glm::dvec3 scale{1, 1, 1};
  glm::dvec3 translate{0, 0, 0};
  std::optional<glm::dvec3> about;  // unset: the caller's default (a mesh's or the scene's centre)
};
glm::dmat4 make_transform(const TransformTerms& t, const glm::dvec3& default_about, const std::string& what);

// Exact text of every entry (cache keys).
std::string transform_key(const glm::dmat4& m);

}  // namespace sn::scene

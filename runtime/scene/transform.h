// Placing meshes: 4x4 affine transforms (world = M * object), checked, and built from the
// rotate / scale / translate terms a script writes.
#pragma once
#include <optional>
#include <string>

#include <glm/glm.hpp>

namespace sn::scene {

// Whether every entry of m is a finite number.
bool is_finite(const glm::dmat4& m);

// The matrix that turns normals under the linear map `m` (a transform's 3x3 part): the inverse
// transpose up to a positive factor, and defined when `m` has none. It is m's cofactor matrix,
// det(m) times the inverse transpose, which takes the normal of a face to the normal of the moved
// face ((m a) x (m b) = cof(m) (a x b)) even when m flattens (a glTF node scaled to zero along
// one axis). Its sign is turned for a mirror, whose winding callers turn instead, and it is
// scaled to a largest entry of 1, so a normal's length after it says nothing of the mesh's size.
// All zeros when m leaves no area (it collapses to a line or a point).
glm::dmat3 normal_matrix(const glm::dmat3& m);

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

#include "scene/transform.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

#include "io/text.h"

namespace sn::scene {

bool is_finite(const glm::dmat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return false;
  return true;
}

glm::dmat3 normal_matrix(const glm::dmat3& m) {
  glm::dmat3 cofactor(glm::cross(m[1], m[2]), glm::cross(m[2], m[0]), glm::cross(m[0], m[1]));
  double largest = 0;
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) largest = std::max(largest, std::abs(cofactor[c][r]));
  if (!(largest > 0) || !std::isfinite(largest)) return glm::dmat3(0.0);
  return cofactor * ((glm::determinant(m) < 0 ? -1.0 : 1.0) / largest);
}

void check_transform(const glm::dmat4& m, const std::string& what) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r]))
        throw std::invalid_argument(what + ": row " + std::to_string(r + 1) + " column " + std::to_string(c + 1) +
                                    " is not a finite number");
  if (m[0][3] != 0 || m[1][3] != 0 || m[2][3] != 0 || m[3][3] != 1)
    throw std::invalid_argument(what + ": the last row must be 0 0 0 1 (an affine transform), got " +
                                io::number_text(m[0][3]) + " " + io::number_text(m[1][3]) + " " +
                                io::number_text(m[2][3]) + " " + io::number_text(m[3][3]));
  const double det = glm::determinant(glm::dmat3(m));
  if (!(std::abs(det) > 1e-12))
    throw std::invalid_argument(what + ": the transform is singular (its 3x3 part has determinant " +
                                io::number_text(det) + "), so it would flatten the mesh");
}

glm::dmat4 make_transform(const TransformTerms& t, const glm::dvec3& default_about, const std::string& what) {
  if (!(glm::length(t.axis) > 1e-12) || !std::isfinite(glm::length(t.axis)))
    throw std::invalid_argument(what + ": the rotation axis must be a non-zero direction");
  if (!std::isfinite(t.degrees)) throw std::invalid_argument(what + ": the rotation angle must be finite");
  const glm::dvec3 about = t.about.value_or(default_about);
  glm::dmat4 m = glm::translate(glm::dmat4(1.0), about + t.translate);
  m = glm::rotate(m, glm::radians(t.degrees), glm::normalize(t.axis));
  m = glm::scale(m, t.scale);
  m = glm::translate(m, -about);
  check_transform(m, what);
  return m;
}

std::string transform_key(const glm::dmat4& m) {
  std::string k;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 3; ++r) {
      // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "," + std::string.
      if (!k.empty()) k += ',';
      k += io::exact_text(m[c][r]);
    }
  return k;
}

}  // namespace sn::scene

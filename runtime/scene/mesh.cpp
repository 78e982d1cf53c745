#include "scene/mesh.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "io/text.h"
#include "scene/tangents.h"
#include "scene/transform.h"

namespace sn::scene {

std::vector<glm::vec3> area_weighted_normals(const std::vector<glm::vec3>& positions,
                                             const std::vector<uint32_t>& indices) {
  std::vector<glm::dvec3> sum(positions.size(), glm::dvec3(0.0));
  for (size_t t = 0; t + 2 < indices.size(); t += 3) {
    uint32_t a = indices[t], b = indices[t + 1], c = indices[t + 2];
    if (a >= positions.size() || b >= positions.size() || c >= positions.size()) continue;
    glm::dvec3 pa(positions[a]), pb(positions[b]), pc(positions[c]);
    glm::dvec3 face = glm::cross(pb - pa, pc - pa);  // |face| = twice the triangle's area
    sum[a] += face, sum[b] += face, sum[c] += face;
  }
  std::vector<glm::vec3> out(positions.size());
  for (size_t i = 0; i < out.size(); ++i) {
    double len = glm::length(sum[i]);
    out[i] = (std::isfinite(len) && len > 0) ? glm::vec3(sum[i] / len) : glm::vec3(0, 1, 0);
  }
  return out;
}

Bounds compute_bounds(const std::vector<glm::vec3>& positions) {
  Bounds b;
  if (positions.empty()) return b;
  b.min = b.max = glm::dvec3(positions[0]);
  for (const auto& p : positions) {
    b.min = glm::min(b.min, glm::dvec3(p));
    b.max = glm::max(b.max, glm::dvec3(p));
  }
  return b;
}

Mesh transformed(const Mesh& m, const glm::dmat4& transform) {
  glm::dmat3 linear(transform);
  double det = glm::determinant(linear);
  if (!is_finite(transform) || !(std::abs(det) > 1e-300))
    throw std::invalid_argument("cannot transform mesh '" + m.name + "': the matrix is singular or not finite");
  const glm::dmat3 normals = normal_matrix(linear);
  Mesh out;
  out.name = m.name;
  out.uvs = m.uvs;
  out.indices = m.indices;
  out.has_normals = m.has_normals;
  out.has_uvs = m.has_uvs;
  out.uv_sets = m.uv_sets;
  out.normals_computed = m.normals_computed;
  out.base_color = m.base_color;
  out.tangent_source = m.tangent_source;
  out.positions.resize(m.positions.size());
  out.normals.resize(m.normals.size());
  for (size_t i = 0; i < m.positions.size(); ++i) {
    const glm::dvec3 p(transform * glm::dvec4(glm::dvec3(m.positions[i]), 1.0));
    // The matrix is finite in double; the vertex must be finite where it is stored, in float.
    out.positions[i] = glm::vec3(p);
    const glm::vec3& f = out.positions[i];
    if (!std::isfinite(f.x) || !std::isfinite(f.y) || !std::isfinite(f.z))
      throw std::invalid_argument("cannot transform mesh '" + m.name + "': vertex " + std::to_string(i + 1) +
                                  " would land at (" + io::number_text(p.x) + ", " + io::number_text(p.y) + ", " +
                                  io::number_text(p.z) + "), beyond a float's range (3.4e38)");
  }
  for (size_t i = 0; i < m.normals.size(); ++i) {
    glm::dvec3 n = normals * glm::dvec3(m.normals[i]);
    double len = glm::length(n);
    out.normals[i] = len > 0 ? glm::vec3(n / len) : glm::vec3(0, 1, 0);
  }
  out.tangents.resize(m.tangents.size());
  for (size_t i = 0; i < m.tangents.size(); ++i) {
    glm::dvec3 n(out.normals[i]), t = linear * glm::dvec3(m.tangents[i]);
    t -= n * glm::dot(n, t);
    double len = glm::length(t);
    out.tangents[i] = len > 1e-12 ? glm::vec4(glm::vec3(t / len), m.tangents[i].w * (det < 0 ? -1.0f : 1.0f))
                                  : fallback_tangent(out.normals[i]);
  }
  // A mirror turns counter-clockwise triangles clockwise; swap two corners to keep them front-facing.
  if (det < 0)
    for (size_t t = 0; t + 2 < out.indices.size(); t += 3) std::swap(out.indices[t + 1], out.indices[t + 2]);
  out.bounds = compute_bounds(out.positions);
  return out;
}

void validate(const Mesh& m) {
  auto fail = [&](const std::string& why) { throw std::runtime_error("mesh '" + m.name + "': " + why); };
  size_t n = m.positions.size();
  if (m.normals.size() != n) fail("has " + std::to_string(m.normals.size()) + " normals for " + std::to_string(n) + " positions");
  if (m.uvs.size() != n) fail("has " + std::to_string(m.uvs.size()) + " uvs for " + std::to_string(n) + " positions");
  if (!m.tangents.empty() && m.tangents.size() != n)
    fail("has " + std::to_string(m.tangents.size()) + " tangents for " + std::to_string(n) + " positions");
  for (size_t i = 0; i < m.tangents.size(); ++i) {
    const auto& t = m.tangents[i];
    if (!std::isfinite(t.x) || !std::isfinite(t.y) || !std::isfinite(t.z) || !(t.w == 1.0f || t.w == -1.0f))
      fail("tangent " + std::to_string(i) + " is not finite with handedness +-1");
  }
  if (m.indices.size() % 3) fail("index count " + std::to_string(m.indices.size()) + " is not a multiple of 3");
  for (size_t i = 0; i < m.indices.size(); ++i)
    if (m.indices[i] >= n)
      fail("index " + std::to_string(m.indices[i]) + " at " + std::to_string(i) + " is outside the " +
           std::to_string(n) + " vertices");
  for (size_t i = 0; i < n; ++i) {
    const auto &p = m.positions[i], &q = m.normals[i];
    const auto& t = m.uvs[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z) || !std::isfinite(q.x) ||
        !std::isfinite(q.y) || !std::isfinite(q.z) || !std::isfinite(t.x) || !std::isfinite(t.y))
      fail("vertex " + std::to_string(i) + " has a non-finite position, normal or uv");
  }
}

}  // namespace sn::scene

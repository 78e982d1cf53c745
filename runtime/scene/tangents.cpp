#include "scene/tangents.h"

#include <cmath>

namespace sn::scene {

namespace {

// v minus its component along unit n, normalised; zero when that leaves (almost) nothing.
glm::dvec3 in_plane(const glm::dvec3& v, const glm::dvec3& n) {
  glm::dvec3 t = v - n * glm::dot(n, v);
  double len = glm::length(t);
  return len > 1e-12 ? t / len : glm::dvec3(0.0);
}

}  // namespace

glm::vec4 fallback_tangent(const glm::vec3& n_in) {
  glm::dvec3 n(n_in);
  glm::dvec3 t = std::abs(n.x) < 0.999 ? in_plane({1, 0, 0}, n) : in_plane({0, 0, 1}, n);
  if (t == glm::dvec3(0.0)) t = {1, 0, 0};  // a zero normal: any unit vector
  return glm::vec4(glm::vec3(t), 1.0f);
}

std::vector<glm::vec4> uv_tangents(const Mesh& m) {
  const std::size_t n = m.positions.size();
  std::vector<glm::vec4> out(n);
  if (!m.has_uvs) {
    for (std::size_t i = 0; i < n; ++i) out[i] = fallback_tangent(m.normals[i]);
    return out;
  }
  std::vector<glm::dvec3> sdir(n, glm::dvec3(0.0)), tdir(n, glm::dvec3(0.0));
  for (std::size_t k = 0; k + 2 < m.indices.size(); k += 3) {
    uint32_t a = m.indices[k], b = m.indices[k + 1], c = m.indices[k + 2];
    glm::dvec3 e1 = glm::dvec3(m.positions[b]) - glm::dvec3(m.positions[a]);
    glm::dvec3 e2 = glm::dvec3(m.positions[c]) - glm::dvec3(m.positions[a]);
    glm::dvec2 d1 = glm::dvec2(m.uvs[b]) - glm::dvec2(m.uvs[a]);
    glm::dvec2 d2 = glm::dvec2(m.uvs[c]) - glm::dvec2(m.uvs[a]);
    double det = d1.x * d2.y - d2.x * d1.y;
    if (!(std::abs(det) > 1e-20)) continue;  // the triangle's UVs have no area: no direction
    // Weighted by the triangle's UV-space size through 1/det: the directions are dP/du, dP/dv.
    glm::dvec3 s = (e1 * d2.y - e2 * d1.y) / det, t = (e2 * d1.x - e1 * d2.x) / det;
    if (!(std::isfinite(s.x + s.y + s.z + t.x + t.y + t.z))) continue;
    for (uint32_t v : {a, b, c}) sdir[v] += s, tdir[v] += t;
  }
  for (std::size_t i = 0; i < n; ++i) {
    glm::dvec3 nn(m.normals[i]);
    glm::dvec3 t = in_plane(sdir[i], nn);
    if (t == glm::dvec3(0.0)) {
      out[i] = fallback_tangent(m.normals[i]);
      continue;
    }
    double w = glm::dot(glm::cross(nn, t), tdir[i]) < 0 ? -1.0 : 1.0;
    out[i] = glm::vec4(glm::vec3(t), float(w));
  }
  return out;
}

std::vector<glm::vec4> mesh_tangents(const Mesh& m) { return m.tangents.empty() ? uv_tangents(m) : m.tangents; }

}  // namespace sn::scene

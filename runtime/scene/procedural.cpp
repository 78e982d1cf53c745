#include "scene/procedural.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace sn::scene {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kMaxDivisions = 4096;

void check_positive(double v, const char* shape, const char* what) {
  if (!(std::isfinite(v) && v > 0))
    throw std::invalid_argument(std::string(shape) + ": " + what + " must be a positive number, got " +
                                std::to_string(v));
}

void check_divisions(int v, int min, const char* shape, const char* what) {
  if (v < min || v > kMaxDivisions)
    throw std::invalid_argument(std::string(shape) + ": " + what + " must be " + std::to_string(min) + ".." +
                                std::to_string(kMaxDivisions) + ", got " + std::to_string(v));
}

void finish(Mesh& m, const char* name) {
  m.name = name;
  m.has_normals = true;
  m.has_uvs = true;
  m.tangent_source = "analytic";
  m.bounds = compute_bounds(m.positions);
}

}  // namespace

Mesh sphere(double radius, int segments, int rings) {
  check_positive(radius, "sphere", "radius");
  check_divisions(segments, 3, "sphere", "segments");
  check_divisions(rings, 2, "sphere", "rings");
  Mesh m;
  for (int i = 0; i <= rings; ++i) {
    double theta = kPi * i / rings;  // polar angle from +Y
    double st = (i == 0 || i == rings) ? 0.0 : std::sin(theta);
    double ct = i == 0 ? 1.0 : i == rings ? -1.0 : std::cos(theta);
    for (int j = 0; j <= segments; ++j) {
      double phi = 2 * kPi * j / segments;
      glm::dvec3 n(st * std::sin(phi), ct, st * std::cos(phi));
      m.normals.push_back(glm::vec3(n));
      m.positions.push_back(glm::vec3(n * radius));
      m.uvs.push_back(glm::vec2(float(double(j) / segments), float(double(i) / rings)));
      // u grows with phi: dP/dphi points along (cos phi, 0, -sin phi); v grows with theta, which is
      // -cross(n, t), so the handedness is -1.
      m.tangents.push_back(glm::vec4(float(std::cos(phi)), 0.f, float(-std::sin(phi)), -1.f));
    }
  }
  auto at = [&](int i, int j) { return uint32_t(i * (segments + 1) + j); };
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      // The triangle touching a pole with two corners would have no area: leave it out.
      if (i != rings - 1) m.indices.insert(m.indices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      if (i != 0) m.indices.insert(m.indices.end(), {at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  finish(m, "sphere");
  return m;
}

Mesh torus(double major, double minor, int segments, int sides) {
  check_positive(major, "torus", "major");
  check_positive(minor, "torus", "minor");
  check_divisions(segments, 3, "torus", "segments");
  check_divisions(sides, 3, "torus", "sides");
  Mesh m;
  for (int i = 0; i <= segments; ++i) {
    double u = 2 * kPi * i / segments;
    glm::dvec3 out(std::sin(u), 0.0, std::cos(u));  // from the axis towards the tube's centre
    for (int j = 0; j <= sides; ++j) {
      double v = 2 * kPi * j / sides;
      glm::dvec3 n = std::cos(v) * out + glm::dvec3(0.0, std::sin(v), 0.0);
      m.normals.push_back(glm::vec3(n));
      m.positions.push_back(glm::vec3(major * out + minor * n));
      m.uvs.push_back(glm::vec2(float(double(i) / segments), float(double(j) / sides)));
      // u grows around the main axis: along (cos u, 0, -sin u); v around the tube, = cross(n, t).
      m.tangents.push_back(glm::vec4(float(std::cos(u)), 0.f, float(-std::sin(u)), 1.f));
    }
  }
  auto at = [&](int i, int j) { return uint32_t(i * (sides + 1) + j); };
  for (int i = 0; i < segments; ++i)
    for (int j = 0; j < sides; ++j)
      m.indices.insert(m.indices.end(),
                       {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i, j + 1)});
  finish(m, "torus");
  return m;
}

Mesh plane(double size, int subdivisions) {
  check_positive(size, "plane", "size");
  check_divisions(subdivisions, 1, "plane", "subdivisions");
  Mesh m;
  int n = subdivisions;
  for (int k = 0; k <= n; ++k)
    for (int i = 0; i <= n; ++i) {
      double s = double(i) / n, t = double(k) / n;
      m.positions.push_back(glm::vec3(float(size * (s - 0.5)), 0.f, float(size * (t - 0.5))));
      m.normals.push_back(glm::vec3(0, 1, 0));
      m.uvs.push_back(glm::vec2(float(s), float(t)));
      m.tangents.push_back(glm::vec4(1, 0, 0, -1));  // u along +X; v along +Z = -cross(+Y, +X)
    }
  auto at = [&](int i, int k) { return uint32_t(k * (n + 1) + i); };
  for (int k = 0; k < n; ++k)
    for (int i = 0; i < n; ++i)
      m.indices.insert(m.indices.end(),
                       {at(i, k), at(i, k + 1), at(i + 1, k + 1), at(i, k), at(i + 1, k + 1), at(i + 1, k)});
  finish(m, "plane");
  return m;
}

}  // namespace sn::scene

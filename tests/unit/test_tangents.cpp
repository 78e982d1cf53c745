// Tangent frames (scene/tangents.h): the G-buffer's tangent and bitangent on the sphere against
// the analytic dP/du and dP/dv, tangents generated from UVs against the analytic ones, the
// fallback frame, transforms and mirrors, and the glTF TANGENT attribute through a file.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include "gl/context.h"
#include "scene/camera.h"
#include "scene/gbuffer.h"
#include "scene/gltf.h"
#include "scene/mesh.h"
#include "scene/procedural.h"
#include "scene/tangents.h"

namespace {

using namespace sn;
using glm::dvec3;

// On a sphere at the origin: the direction of increasing u (longitude) and of increasing v
// (colatitude, from +Y down) at point p.
dvec3 analytic_tangent(const dvec3& p) {
  double phi = std::atan2(p.x, p.z);
  return {std::cos(phi), 0, -std::sin(phi)};
}
dvec3 analytic_bitangent(const dvec3& p) {
  dvec3 n = glm::normalize(p);
  double phi = std::atan2(p.x, p.z), ct = n.y, st = std::sqrt(std::max(0.0, 1 - ct * ct));
  return {ct * std::sin(phi), -st, ct * std::cos(phi)};
}

TEST(Tangents, GBufferMatchesTheAnalyticSphereFrame) {
  gl::current();
  const int W = 120, H = 100;
  scene::Mesh sphere = scene::sphere(1.0, 64, 32);
  scene::Camera camera{{0.4, 0.8, 3.0}, {0, 0, 0}};
  auto g = scene::render_gbuffer({{&sphere}}, camera, W, H, {"normal", "tangent", "bitangent", "world_position"});
  io::Image normal = g.target->read(0), tangent = g.target->read(1), bitangent = g.target->read(2),
            world = g.target->read(3);
  int compared = 0;
  double worst_t = 0, worst_b = 0, worst_perp = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      if (!(normal.at(x, y, 3) > 0.5f)) continue;
      dvec3 p(world.at(x, y, 0), world.at(x, y, 1), world.at(x, y, 2));
      if (std::abs(p.y) > 0.95) continue;  // near a pole the longitude turns fast
      dvec3 n(normal.at(x, y, 0), normal.at(x, y, 1), normal.at(x, y, 2));
      dvec3 t(tangent.at(x, y, 0), tangent.at(x, y, 1), tangent.at(x, y, 2));
      dvec3 b(bitangent.at(x, y, 0), bitangent.at(x, y, 1), bitangent.at(x, y, 2));
      ++compared;
      worst_t = std::max(worst_t, std::acos(std::min(1.0, glm::dot(t, analytic_tangent(p)))));
      worst_b = std::max(worst_b, std::acos(std::min(1.0, glm::dot(b, glm::normalize(analytic_bitangent(p))))));
      worst_perp = std::max(worst_perp, std::abs(glm::dot(n, t)) + std::abs(glm::dot(n, b)) + std::abs(glm::length(t) - 1));
    }
  printf("[ sphere ] %d pixels: tangent within %.4f rad, bitangent within %.4f rad, |n.t| + |n.b| + ||t| - 1| <= %.2g\n",
         compared, worst_t, worst_b, worst_perp);
  EXPECT_GT(compared, 3000);
  // 64 segments: vertex tangents 5.6 degrees apart, interpolated across the triangle.
  EXPECT_LT(worst_t, 0.01);
  EXPECT_LT(worst_b, 0.01);
  EXPECT_LT(worst_perp, 1e-5);
}

TEST(Tangents, FromUvsMatchTheAnalyticOnes) {
  for (bool torus : {false, true}) {
    scene::Mesh m = torus ? scene::torus(1.0, 0.3, 48, 24) : scene::sphere(1.0, 48, 24);
    std::vector<glm::vec4> analytic = m.tangents;
    m.tangents.clear();
    std::vector<glm::vec4> generated = scene::uv_tangents(m);
    ASSERT_EQ(generated.size(), analytic.size());
    // Inside, a vertex's triangles lie on both sides and their chords nearly average to the
    // analytic direction (the quads' diagonals break the symmetry a little: 0.01 rad measured on
    // the sphere, 0.002 on the torus); on a UV seam they lie on one side only: off by up to half a
    // segment's angle.
    double worst = 0, worst_seam = 0;
    int compared = 0;
    for (std::size_t i = 0; i < generated.size(); ++i) {
      if (!torus && std::abs(m.positions[i].y) > 0.99f) continue;  // the poles' UVs collapse
      ++compared;
      double angle = std::acos(std::min(1.0, double(glm::dot(glm::vec3(generated[i]), glm::vec3(analytic[i])))));
      glm::vec2 uv = m.uvs[i];
      bool seam = uv.x == 0 || uv.x == 1 || (torus && (uv.y == 0 || uv.y == 1));
      (seam ? worst_seam : worst) = std::max(seam ? worst_seam : worst, angle);
      EXPECT_EQ(generated[i].w, analytic[i].w) << (torus ? "torus" : "sphere") << " vertex " << i;
    }
    printf("[ %s ] %d vertices: generated tangents within %.2g rad of the analytic ones (%.2g on the seams)\n",
           torus ? "torus" : "sphere", compared, worst, worst_seam);
    EXPECT_LT(worst, 0.02);
    EXPECT_LT(worst_seam, 3.14159265 / (torus ? 24 : 48) * 1.05);
  }
}

TEST(Tangents, FallbackFrameIsPerpendicularAndUnit) {
  for (glm::vec3 n : {glm::vec3(0, 1, 0), glm::vec3(1, 0, 0), glm::vec3(-1, 0, 0), glm::normalize(glm::vec3(1, 2, 3)),
                      glm::vec3(0, 0, -1)}) {
    glm::vec4 t = scene::fallback_tangent(n);
    EXPECT_NEAR(glm::length(glm::vec3(t)), 1.0, 1e-6);
    EXPECT_NEAR(glm::dot(glm::vec3(t), n), 0.0, 1e-6);
    EXPECT_EQ(t.w, 1.0f);
  }
  EXPECT_EQ(scene::fallback_tangent({0, 1, 0}), glm::vec4(1, 0, 0, 1));  // +X where it can be
  scene::Mesh flat = scene::plane();
  flat.has_uvs = false;
  flat.tangents.clear();
  for (const auto& t : scene::uv_tangents(flat)) EXPECT_EQ(t, glm::vec4(1, 0, 0, 1));
}

TEST(Tangents, TransformsCarryThemAndMirrorsFlipHandedness) {
  scene::Mesh m = scene::sphere(1.0, 16, 8);
  glm::dmat4 rot = glm::dmat4(glm::dmat3(0, 0, -1, 0, 1, 0, 1, 0, 0));  // 90 degrees about +Y
  scene::Mesh r = scene::transformed(m, rot);
  for (std::size_t i = 0; i < m.tangents.size(); ++i) {
    glm::vec3 want = glm::vec3(glm::dmat3(rot) * dvec3(glm::vec3(m.tangents[i])));
    EXPECT_NEAR(glm::length(glm::vec3(r.tangents[i]) - want), 0.0, 1e-5);
    EXPECT_EQ(r.tangents[i].w, m.tangents[i].w);
  }
  scene::Mesh mirrored = scene::transformed(m, glm::scale(glm::dmat4(1.0), dvec3(-1, 1, 1)));
  for (std::size_t i = 0; i < m.tangents.size(); ++i) EXPECT_EQ(mirrored.tangents[i].w, -m.tangents[i].w);
}

TEST(Tangents, GltfTangentAttributeRoundTrips) {
  scene::Mesh m = scene::torus(1.0, 0.3, 12, 8);
  std::string path = ::testing::TempDir() + "tangents.glb";
  scene::save_glb(m, path);
  scene::Mesh back = scene::load_mesh(path);
  std::remove(path.c_str());
  EXPECT_EQ(back.tangent_source, "file");
  ASSERT_EQ(back.tangents.size(), m.tangents.size());
  for (std::size_t i = 0; i < m.tangents.size(); ++i) {
    EXPECT_NEAR(glm::length(glm::vec3(back.tangents[i]) - glm::vec3(m.tangents[i])), 0.0, 1e-6);
    EXPECT_EQ(back.tangents[i].w, m.tangents[i].w);
  }
  // A file without TANGENT leaves them to be generated when drawn.
  m.tangents.clear();
  scene::save_glb(m, path);
  EXPECT_TRUE(scene::load_mesh(path).tangents.empty());
  std::remove(path.c_str());
}

}  // namespace

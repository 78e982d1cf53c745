// Camera: view and projection matrices against hand-computed ones, pixel rays that project back
// onto their pixels, orbit placement, and the errors for impossible cameras.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <optional>
#include <vector>

#include "scene/camera.h"
#include "scene/scene.h"

using namespace sn::scene;

namespace {

constexpr double kPi = 3.14159265358979323846;

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

void expect_mat(const glm::dmat4& got, const double (&rows)[4][4], double tol) {
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(got[c][r], rows[r][c], tol) << "row " << r << " column " << c;
}

}  // namespace

TEST(Camera, ViewFromPlusZIsATranslation) {
  Camera c({0, 0, 5}, {0, 0, 0});
  const double want[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, -5}, {0, 0, 0, 1}};
  expect_mat(c.view(), want, 1e-15);
}

TEST(Camera, ViewFromPlusXTurnsTheWorld) {
  // Looking from (3,0,0) at the origin: forward f = -X, side s = f x up = -Z, up u = s x f = +Y.
  // Rows of the view are s, u, -f; the translation is (-s.e, -u.e, f.e) = (0, 0, -3).
  Camera c({3, 0, 0}, {0, 0, 0});
  const double want[4][4] = {{0, 0, -1, 0}, {0, 1, 0, 0}, {1, 0, 0, -3}, {0, 0, 0, 1}};
  expect_mat(c.view(), want, 1e-15);
  // So +Z, seen from +X with +Y up, is on the left of the picture.
  glm::dvec4 p = c.view() * glm::dvec4(0, 0, 1, 1);
  EXPECT_NEAR(p.x, -1, 1e-15);
  EXPECT_NEAR(p.z, -3, 1e-15);
}

TEST(Camera, PerspectiveMatchesTheOpenGLFormula) {
  // fov 90 (tan 45 = 1), aspect 2, near 1, far 3:
  // [1/(a t), 0, 0, 0; 0, 1/t, 0, 0; 0, 0, -(f+n)/(f-n), -2fn/(f-n); 0, 0, -1, 0]
  Camera c({0, 0, 1}, {0, 0, 0}, {0, 1, 0}, 90, 2, 1, 3);
  const double want[4][4] = {{0.5, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, -2, -3}, {0, 0, -1, 0}};
  expect_mat(c.projection(c.aspect()), want, 1e-15);
  // The near plane lands on depth -1, the far plane on +1.
  glm::dvec4 n = c.projection(2) * glm::dvec4(0, 0, -1, 1), f = c.projection(2) * glm::dvec4(0, 0, -3, 1);
  EXPECT_NEAR(n.z / n.w, -1, 1e-15);
  EXPECT_NEAR(f.z / f.w, 1, 1e-15);
}

TEST(Camera, AspectFollowsTheTargetUnlessTheCameraHasOne) {
  Camera follows({0, 0, 3}, {0, 0, 0});
  EXPECT_DOUBLE_EQ(follows.aspect_for(160, 120), 160.0 / 120.0);
  Camera fixed({0, 0, 3}, {0, 0, 0}, {0, 1, 0}, 45, 2.0);
  EXPECT_DOUBLE_EQ(fixed.aspect_for(160, 120), 2.0);
}

TEST(Camera, PixelRaysProjectBackOntoTheirPixelCentres) {
  Camera c({1.5, 0.7, 2.5}, {0.2, -0.1, 0}, {0, 1, 0}, 50, 0, 0.1, 100);
  const int w = 160, h = 90;
  glm::dmat4 pv = c.projection(c.aspect_for(w, h)) * c.view();
  for (int y : {0, 17, 44, 89})
    for (int x : {0, 80, 121, 159}) {
      Ray r = c.ray(x, y, w, h);
      EXPECT_NEAR(glm::length(r.direction), 1, 1e-12);
      glm::dvec4 clip = pv * glm::dvec4(r.origin + 4.0 * r.direction, 1);
      double px = (clip.x / clip.w * 0.5 + 0.5) * w, py = (0.5 - clip.y / clip.w * 0.5) * h;  // image rows top first
      EXPECT_NEAR(px, x + 0.5, 1e-9) << x << "," << y;
      EXPECT_NEAR(py, y + 0.5, 1e-9) << x << "," << y;
    }
  // The centre of an odd-sized image looks straight at the target.
  Ray mid = c.ray(80, 45, 161, 91);
  EXPECT_NEAR(glm::length(glm::cross(mid.direction, glm::normalize(c.target() - c.eye()))), 0, 1e-12);
}

TEST(Camera, OrbitPlacesCamerasEvenlyAtDistanceAndElevation) {
  OrbitOptions o;
  o.count = 8;
  o.elevation = 30;
  o.distance = 4;
  o.target = {1, 2, 3};
  auto cams = orbit(o);
  ASSERT_EQ(cams.size(), 8u);
  for (int k = 0; k < 8; ++k) {
    glm::dvec3 d = cams[size_t(k)].eye() - o.target;
    EXPECT_NEAR(glm::length(d), 4, 1e-12);
    EXPECT_NEAR(std::asin(d.y / 4) * 180 / kPi, 30, 1e-10);
    double azimuth = std::atan2(d.x, d.z) * 180 / kPi;  // from +Z towards +X
    EXPECT_NEAR(std::remainder(azimuth - 45.0 * k, 360.0), 0, 1e-10) << k;
    EXPECT_EQ(cams[size_t(k)].target(), o.target);
  }
  // Camera 1 sits on the +Z side: eye = target + 4 (0, sin 30, cos 30).
  EXPECT_NEAR(cams[0].eye().x, 1, 1e-12);
  EXPECT_NEAR(cams[0].eye().y, 2 + 2, 1e-12);
  EXPECT_NEAR(cams[0].eye().z, 3 + 4 * std::cos(kPi / 6), 1e-12);
}

TEST(Camera, OrbitNextToAPoleLooksAtItsTarget) {
  // Within 1e-6 of the world's up the look-at had no sideways axis; every elevation inside
  // (-90, 90) places a camera whose picture is upright along the rising elevation.
  for (double elevation : {89.9999999, -89.9999999, 89.95, 89.0}) {
    OrbitOptions o;
    o.count = 4;
    o.elevation = elevation;
    std::vector<Camera> cams;
    ASSERT_EQ(error_of([&] { cams = orbit(o); }), "") << elevation;
    for (const Camera& c : cams) {
      const glm::dvec3 forward = glm::normalize(c.target() - c.eye());
      EXPECT_NEAR(std::asin(-forward.y) * 180 / kPi, elevation, 1e-6) << elevation;
      const glm::dvec4 target_in_view = c.view() * glm::dvec4(c.target(), 1.0);
      EXPECT_NEAR(target_in_view.x, 0, 1e-9);
      EXPECT_NEAR(target_in_view.y, 0, 1e-9);
    }
  }
}

TEST(Camera, ImpossibleCamerasAreClearErrors) {
  EXPECT_EQ(error_of([] { Camera({1, 1, 1}, {1, 1, 1}); }), "camera: eye and target are the same point");
  EXPECT_NE(error_of([] { Camera({0, 3, 0}, {0, 0, 0}); }).find("up is parallel"), std::string::npos);
  EXPECT_NE(error_of([] { Camera({0, 0, 3}, {0, 0, 0}, {0, 1, 0}, 180); }).find("fov must be in (0, 180)"),
            std::string::npos);
  EXPECT_NE(error_of([] { Camera({0, 0, 3}, {0, 0, 0}, {0, 1, 0}, 45, 1, 0); }).find("near must be > 0"),
            std::string::npos);
  EXPECT_NE(error_of([] { Camera({0, 0, 3}, {0, 0, 0}, {0, 1, 0}, 45, 1, 2, 1); }).find("far (1) must be greater"),
            std::string::npos);
  EXPECT_NE(error_of([] { Camera({0, 0, NAN}, {0, 0, 0}); }).find("must be finite"), std::string::npos);
  // Past near * 2^24 depths round to 1 and surfaces vanish (a sphere at distance 3 did at 3e-8).
  EXPECT_NE(error_of([] { Camera({0, 0, 3}, {0, 0, 0}, {0, 1, 0}, 45, 1, 3e-8, 10); })
                .find("near (3e-08) is too small for far (10): depths past about near * 2^24"),
            std::string::npos);
  EXPECT_EQ(error_of([] { Camera({0, 0, 3}, {0, 0, 0}, {0, 1, 0}, 45, 1, 10.0 / 16777216, 10); }), "");
  OrbitOptions o;
  o.elevation = 90;
  EXPECT_NE(error_of([&] { orbit(o); }).find("elevation must be in (-90, 90)"), std::string::npos);
  o.elevation = 0;
  o.count = 0;
  EXPECT_NE(error_of([&] { orbit(o); }).find("count must be 1.."), std::string::npos);
  // A field of view of 0 names the field of view, not the infinite distance it would frame at.
  EXPECT_EQ(error_of([] { framing_orbit(Bounds{{-1, -1, -1}, {1, 1, 1}}, 4, 20, 0, std::nullopt); }),
            "camera: fov must be in (0, 180) degrees, got 0");
  EXPECT_EQ(error_of([] { check_fov(180); }), "camera: fov must be in (0, 180) degrees, got 180");
  EXPECT_EQ(error_of([] { check_fov(60); }), "");
}

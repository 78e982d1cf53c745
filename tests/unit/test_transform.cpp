// Transforms that place meshes and poses: the order of the terms, the pivot, and the checks.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "scene/transform.h"

namespace {

using sn::scene::make_transform;
using sn::scene::TransformTerms;

glm::dvec3 apply(const glm::dmat4& m, glm::dvec3 p) { return glm::dvec3(m * glm::dvec4(p, 1.0)); }

void expect_near(glm::dvec3 a, glm::dvec3 b) {
  EXPECT_NEAR(a.x, b.x, 1e-12);
  EXPECT_NEAR(a.y, b.y, 1e-12);
  EXPECT_NEAR(a.z, b.z, 1e-12);
}

TEST(Transform, ScaleThenRotateAboutThePivotThenTranslate) {
  TransformTerms t;
  t.degrees = 90;
  t.axis = {0, 0, 2};  // normalised: +z
  t.scale = {2, 1, 1};
  t.translate = {0, 0, 5};
  const glm::dvec3 about{1, 1, 0};
  const glm::dmat4 m = make_transform(t, about, "test");
  expect_near(apply(m, about), about + t.translate);  // the pivot only moves by the translation
  // x + (1, 0, 0) from the pivot: scaled to (2, 0, 0), turned +90 about z to (0, 2, 0).
  expect_near(apply(m, about + glm::dvec3(1, 0, 0)), about + glm::dvec3(0, 2, 5));
  t.about = glm::dvec3(0, 0, 0);  // an explicit pivot wins over the caller's default
  expect_near(apply(make_transform(t, about, "test"), {0, 0, 0}), {0, 0, 5});
}

TEST(Transform, ChecksNameTheProblem) {
  glm::dmat4 m(1.0);
  m[0][3] = 0.5;  // row 4, column 1
  try {
    sn::scene::check_transform(m, "pose 2");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("pose 2: the last row must be 0 0 0 1"), std::string::npos) << e.what();
  }
  TransformTerms flat;
  flat.scale = {1, 0, 1};
  EXPECT_THROW(make_transform(flat, {0, 0, 0}, "x"), std::invalid_argument);
  TransformTerms no_axis;
  no_axis.degrees = 10;
  no_axis.axis = {0, 0, 0};
  EXPECT_THROW(make_transform(no_axis, {0, 0, 0}, "x"), std::invalid_argument);
  glm::dmat4 nan(1.0);
  nan[3][1] = std::nan("");
  EXPECT_THROW(sn::scene::check_transform(nan, "x"), std::invalid_argument);
}

}  // namespace

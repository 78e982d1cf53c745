// Colour spaces: the CPU twin against published values and its own inverses, and the GLSL
// conversions (shaders/include/color.glsl) against the twin on 100k random colours per space,
// both directions, within 1e-5.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "gl/context.h"
#include "shading/color.h"
#include "shading/lighting_gpu.h"

namespace {

using namespace sn::shading;
using sn::shading::ColorSpace;
using glm::dvec3;

const ColorSpace kSpaces[] = {ColorSpace::rgb, ColorSpace::hsv, ColorSpace::cie_xyz, ColorSpace::cie_lab};

void expect_near3(const dvec3& a, const dvec3& b, double tol) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], tol) << "channel " << c;
}

TEST(Color, HsvOfThePrimaries) {
  expect_near3(rgb_to_hsv({1, 0, 0}), {0, 1, 1}, 0);
  expect_near3(rgb_to_hsv({0, 1, 0}), {1.0 / 3, 1, 1}, 1e-15);
  expect_near3(rgb_to_hsv({0, 0, 1}), {2.0 / 3, 1, 1}, 1e-15);
  expect_near3(rgb_to_hsv({1, 1, 0}), {1.0 / 6, 1, 1}, 1e-15);
  expect_near3(rgb_to_hsv({0.5, 0.5, 0.5}), {0, 0, 0.5}, 0);  // greys: hue 0, saturation 0
  expect_near3(rgb_to_hsv({1, 0, 0.5}), {11.0 / 12, 1, 1}, 1e-15);  // magenta-red wraps below 1
  expect_near3(hsv_to_rgb({1.0 / 6, 0.5, 0.8}), {0.8, 0.8, 0.4}, 1e-15);
  // A hue just below 0 wraps to one that rounds to 6/6: H stays in [0, 1), as the docs say.
  EXPECT_EQ(rgb_to_hsv({1, 0, 1e-17}).x, 0.0);
}

TEST(Color, XyzAndLabOfKnownColours) {
  // sRGB D65 white and the red primary (Lindbloom's tables).
  expect_near3(rgb_to_xyz({1, 1, 1}), {0.95047, 1.0000001, 1.08883}, 1e-12);
  expect_near3(xyz_to_lab(rgb_to_xyz({1, 1, 1})), {100, 0, 0}, 1e-9);
  expect_near3(xyz_to_lab(rgb_to_xyz({1, 0, 0})), {53.2408, 80.0925, 67.2032}, 1e-3);
  expect_near3(xyz_to_lab(rgb_to_xyz({0, 0, 0})), {0, 0, 0}, 1e-12);
  // The encoding a network learns: white -> (1, 128/255, 128/255).
  expect_near3(encode_color(ColorSpace::cie_lab, {1, 1, 1}), {1, 128.0 / 255, 128.0 / 255}, 1e-9);
  // Dark colours use the linear segment of f.
  dvec3 dark(0.001, 0.002, 0.0005);
  expect_near3(lab_to_xyz(xyz_to_lab(rgb_to_xyz(dark))), rgb_to_xyz(dark), 1e-15);
}

TEST(Color, EveryEncodingRoundTripsInDouble) {
  std::mt19937_64 g(7);
  std::uniform_real_distribution<double> u(0, 1);
  for (ColorSpace s : kSpaces)
    for (int i = 0; i < 100000; ++i) {
      dvec3 c(u(g), u(g), u(g));
      dvec3 back = decode_color(s, encode_color(s, c));
      for (int k = 0; k < 3; ++k) ASSERT_NEAR(back[k], c[k], 1e-12) << sn::shading::color_space_name(s);
    }
}

// Hue is an angle: 0.9999999 and 0 are neighbours.
double channel_error(ColorSpace s, int c, double a, double b) {
  double e = std::abs(a - b);
  if (s == ColorSpace::hsv && c == 0) e = std::min(e, 1 - e);
  return e;
}

TEST(Color, ShaderMatchesTwinBothWaysOn100kColours) {
  sn::gl::current();
  std::mt19937_64 g(11);
  std::uniform_real_distribution<float> u(0, 1);
  const int n = 100000;
  std::vector<glm::vec3> rgb(n);
  for (auto& c : rgb) c = {u(g), u(g), u(g)};
  rgb[0] = {0, 0, 0}, rgb[1] = {1, 1, 1}, rgb[2] = {0.5f, 0.5f, 0.5f}, rgb[3] = {1, 0, 1e-7f};
  for (ColorSpace s : kSpaces) {
    SCOPED_TRACE(sn::shading::color_space_name(s));
    auto enc = convert_colors(rgb, s, false);
    std::vector<glm::vec3> twin_enc(n);
    double max_fwd = 0, max_inv = 0, max_trip = 0;
    for (int i = 0; i < n; ++i) {
      dvec3 t = encode_color(s, dvec3(rgb[i]));
      twin_enc[i] = glm::vec3(t);
      for (int c = 0; c < 3; ++c) max_fwd = std::max(max_fwd, channel_error(s, c, enc[i][c], t[c]));
    }
    auto dec = convert_colors(twin_enc, s, true);
    auto trip = convert_colors(enc, s, true);
    for (int i = 0; i < n; ++i) {
      dvec3 t = decode_color(s, dvec3(twin_enc[i]));
      for (int c = 0; c < 3; ++c) {
        max_inv = std::max(max_inv, std::abs(double(dec[i][c]) - t[c]));
        max_trip = std::max(max_trip, std::abs(double(trip[i][c]) - double(rgb[i][c])));
      }
    }
    printf("[ %s ] max |gpu - twin|: encode %.3g, decode %.3g; gpu round trip %.3g\n",
           sn::shading::color_space_name(s), max_fwd, max_inv, max_trip);
    EXPECT_LE(max_fwd, 1e-5);
    EXPECT_LE(max_inv, 1e-5);
    EXPECT_LE(max_trip, 1e-5);
    if (s != ColorSpace::rgb) EXPECT_GT(max_fwd, 0.0);  // float really differs from double: the GPU ran
    if (s == ColorSpace::hsv)  // hue in [0, 1): (1, 0, 1e-7)'s rounded to 1 in float
      for (int i = 0; i < n; ++i) ASSERT_LT(enc[i][0], 1.0f) << rgb[i].r << " " << rgb[i].g << " " << rgb[i].b;
  }
}

TEST(Color, DecodingArbitraryNetworkOutputsNeverGivesNaN) {
  sn::gl::current();
  std::vector<glm::vec3> wild = {{-5, 3, 9}, {1e6, -1e6, 0}, {0, 0, 0}, {-0.5, 2, -3}, {1e-30f, 0, 0}};
  for (ColorSpace s : kSpaces) {
    for (const auto& c : convert_colors(wild, s, true))
      for (int k = 0; k < 3; ++k) EXPECT_TRUE(std::isfinite(c[k])) << sn::shading::color_space_name(s);
    for (const auto& c : wild)
      for (int k = 0; k < 3; ++k) EXPECT_TRUE(std::isfinite(decode_color(s, dvec3(c))[k]));
  }
}

}  // namespace

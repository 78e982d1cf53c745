// The lighting shaders against their double-precision CPU twin (runtime/shading/lighting.cpp):
// 100k random samples per model (10 random parameter sets x 10k), every output channel within
// 1e-5 of the twin. Inputs are drawn in float and handed to both sides as the same floats.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "gl/context.h"
#include "shading/lighting.h"
#include "shading/lighting_gpu.h"

namespace {

using namespace sn::shading;
using sn::scene::Light;
using sn::scene::make_light;
using glm::dvec3;

struct Rng {
  std::mt19937_64 g;
  explicit Rng(uint64_t seed) : g(seed) {}
  double uniform(double lo = 0, double hi = 1) { return lo + (hi - lo) * double(g() >> 11) * 0x1p-53; }
  // Float-exact values, so the GPU (float) and the twin (double) see the same number.
  double f(double lo = 0, double hi = 1) { return double(float(uniform(lo, hi))); }
  double log_uniform(double lo, double hi) { return double(float(std::exp(uniform(std::log(lo), std::log(hi))))); }
  glm::vec3 direction() {
    for (;;) {
      dvec3 d(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
      double l = glm::length(d);
      if (l > 1e-3 && l <= 1) return glm::vec3(d / l);
    }
  }
  std::vector<double> color() { return {f(), f(), f()}; }
};

// Random parameters inside each model's everyday range (see the exponent note in docs/lighting.md).
LightingParams random_params(const std::string& m, Rng& r) {
  std::map<std::string, std::vector<double>> v;
  if (m == "phong" || m == "blinn_phong" || m == "textured_phong") {
    v = {{"color", r.color()}, {"ambient", {r.f()}}, {"specular", r.color()},
         {"shininess", {r.log_uniform(1, m == "blinn_phong" ? 2000 : 1000)}}};
  } else if (m == "ggx") {
    v = {{"roughness", {r.f(0.05, 1)}}, {"f0", r.color()}, {"diffuse", r.color()}, {"ambient", {r.f(0, 0.3)}}};
  } else if (m == "toon3") {
    std::vector<double> t = {r.f(0, 1.5), r.f(0, 1.5), r.f(0, 1.5), r.f(0, 1.5)};
    std::sort(t.begin(), t.end());
    v = {{"ambient", r.color()}, {"diffuse", r.color()}, {"specular", r.color()}, {"a", {r.f()}},
         {"thresholds", t}, {"shininess", {r.log_uniform(1, 1000)}}, {"ambient_weight", {r.f()}},
         {"specular_weight", {r.f()}}};
  }
  return make_params(m, v);
}

Light random_light(Rng& r) {
  glm::vec3 d = r.direction();
  Light l = make_light(dvec3(d), dvec3(r.f(0.5, 1.5), r.f(0.5, 1.5), r.f(0.5, 1.5)));
  l.dir = dvec3(glm::vec3(l.dir));  // the GPU gets float(dir); so does the twin
  return l;
}

class LightingTwin : public ::testing::TestWithParam<std::string> {};

TEST_P(LightingTwin, ShaderMatchesDoubleTwinWithin1e5) {
  sn::gl::current();
  const std::string m = GetParam();
  const std::vector<std::string> order = {"phong", "blinn_phong", "ggx", "toon3", "textured_phong"};
  Rng r(1234 + int(std::find(order.begin(), order.end(), m) - order.begin()));
  const int kSets = 10, kSamples = 10000;
  double max_err = 0;
  int skipped = 0, compared = 0;
  for (int set = 0; set < kSets; ++set) {
    LightingParams p = random_params(m, r);
    Light light = random_light(r);
    std::vector<glm::vec3> n(kSamples), v(kSamples), base(kSamples);
    for (int i = 0; i < kSamples; ++i) {
      // Unnormalised on purpose: the model normalises.
      n[i] = r.direction() * float(r.uniform(0.5, 2));
      v[i] = r.direction() * float(r.uniform(0.5, 2));
      base[i] = glm::vec3(r.f(), r.f(), r.f());
    }
    auto gpu = evaluate(p, light, n, v, base);
    for (int i = 0; i < kSamples; ++i) {
      // Within 1e-4 of a branch (n.l = 0, n.v = 0, a toon threshold) float may take the other side.
      if (near_discontinuity(p, light, dvec3(n[i]), dvec3(v[i]), 1e-4)) {
        ++skipped;
        continue;
      }
      dvec3 twin = shade(p, light, dvec3(n[i]), dvec3(v[i]), dvec3(base[i]));
      for (int c = 0; c < 3; ++c) {
        double e = std::abs(double(gpu[i][c]) - twin[c]);
        max_err = std::max(max_err, e);
        ASSERT_LE(e, 1e-5) << p.describe() << " sample " << i << " channel " << c << ": gpu " << gpu[i][c]
                           << " twin " << twin[c];
      }
      ++compared;
    }
  }
  printf("[ %s ] %d samples compared, %d near a branch skipped, max |gpu - twin| = %.3g\n",
         m.c_str(), compared, skipped, max_err);
  EXPECT_LT(skipped, kSets * kSamples / 50);  // the exclusion stays a thin band
  EXPECT_GT(max_err, 0.0);                    // the GPU really ran (float differs from double somewhere)
}

INSTANTIATE_TEST_SUITE_P(Models, LightingTwin,
                         ::testing::Values(std::string("phong"), std::string("blinn_phong"), std::string("ggx"),
                                           std::string("toon3"), std::string("textured_phong")),
                         [](const auto& info) { return info.param; });

}  // namespace

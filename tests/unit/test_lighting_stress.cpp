// The numerical stress test (shading/stress.h): every model at its defaults and at the edges of
// its domain, over the adversarial grid, on the GPU and the twin: zero NaN, Inf, negative and
// over-bound outputs, and what datasets record stays inside each colour space's range.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "gl/context.h"
#include "shading/lighting.h"
#include "shading/stress.h"

namespace {

using namespace sn::shading;
using sn::scene::Light;
using sn::scene::make_light;

TEST(LightingStress, GridCoversTheAdversarialCases) {
  Light light = stress_lights().at(1);  // along +Y: exact zeros are representable
  auto grid = adversarial_grid(light);
  ASSERT_GT(grid.size(), 10000u);
  int zero_n = 0, exact_grazing = 0, tiny_above = 0, v_is_minus_l = 0, huge = 0;
  for (const auto& s : grid) {
    glm::dvec3 n(s.n), v(s.v);
    if (glm::length(n) == 0) ++zero_n;
    if (glm::length(n) > 1e20) ++huge;  // its square overflows float
    if (glm::length(n) == 0 || glm::length(v) == 0) continue;
    double nl = glm::dot(glm::vec3(glm::normalize(n)), glm::vec3(light.dir));  // as the GPU sees it
    if (nl == 0) ++exact_grazing;
    if (nl > 5e-8 && nl < 2e-7) ++tiny_above;
    if (glm::length(glm::normalize(v) + light.dir) < 1e-6) ++v_is_minus_l;
  }
  EXPECT_GT(zero_n, 0);
  EXPECT_GT(huge, 0);
  EXPECT_GT(exact_grazing, 0);
  EXPECT_GT(tiny_above, 0);
  EXPECT_GT(v_is_minus_l, 0);
}

TEST(LightingStress, EveryModelAtItsExtremesHasZeroNanInfOrOutOfRange) {
  sn::gl::current();
  auto cases = stress_cases();
  ASSERT_GE(cases.size(), 17u);
  for (const auto& c : cases) {
    StressResult r = stress_test(c.params, stress_lights());
    SCOPED_TRACE(c.label);
    EXPECT_GT(r.samples, 20000u);
    EXPECT_EQ(r.gpu.nan, 0u);
    EXPECT_EQ(r.gpu.inf, 0u);
    EXPECT_EQ(r.gpu.negative, 0u);
    EXPECT_EQ(r.gpu.over, 0u);
    EXPECT_EQ(r.twin.nan, 0u);
    EXPECT_EQ(r.twin.inf, 0u);
    EXPECT_EQ(r.twin.negative, 0u);
    EXPECT_EQ(r.twin.over, 0u);
    EXPECT_EQ(r.encoded_nan, 0u);
    EXPECT_EQ(r.encoded_out_of_range, 0u);
    EXPECT_GT(r.max_raw, 0.0);  // the models really produced light on this grid
  }
}

// sn.lighting.define holds a definition's GLSL to its twin (hold_twin); the built-ins, which
// register without it, pass it too where define would hold them, and at every edge of their
// domain the stress table covers (exponents 1e6, roughness 0, equal toon thresholds), so the
// tolerance and the rounding it forgives are what a correct float shader needs.
TEST(LightingStress, BuiltinsHoldToTheirTwinsAsDefineHoldsADefinition) {
  sn::gl::current();
  for (const auto& m : models()) {
    if (!m->builtin) continue;
    for (const auto& p : hold_params(m)) {
      SCOPED_TRACE(p.describe());
      TwinMismatch miss = hold_twin(p, hold_light());
      EXPECT_FALSE(miss.failed) << "gpu " << miss.gpu.x << " twin " << miss.twin.x << " difference " << miss.difference;
    }
  }
  for (const auto& c : stress_cases()) {
    SCOPED_TRACE(c.label);
    for (const Light& light : stress_lights()) {
      TwinMismatch miss = hold_twin(c.params, light);
      EXPECT_FALSE(miss.failed) << "gpu " << miss.gpu.x << " twin " << miss.twin.x << " difference " << miss.difference;
    }
  }
}

// The hold finds a twin that is wrong where the GLSL is not: off by a factor, or NaN where n.l < 0,
// and names the point; a twin that agrees but for a toon step float and double take apart passes.
TEST(LightingStress, HoldFindsAWrongTwinAndForgivesRounding) {
  sn::gl::current();
  auto define = [](const std::string& name, std::string glsl, std::function<glm::dvec3(double nl)> twin) {
    LightingModel m;
    m.name = name;
    m.glsl_source = std::move(glsl);
    m.glsl_name = name + ".glsl";
    m.twin = [twin](const Surface& s, const LightingParams&) { return twin(glm::dot(s.n, s.l)); };
    LightingParams p;
    p.model = std::make_shared<const LightingModel>(m);
    return p;
  };
  const std::string lambert = "vec3 shade(Surface s, Params p) { return vec3(max(dot(s.n, s.l), 0.0)); }";
  auto half = define("hold_half", lambert, [](double nl) { return glm::dvec3(0.5 * std::max(nl, 0.0)); });
  TwinMismatch miss = hold_twin(half, hold_light());
  ASSERT_TRUE(miss.failed);
  EXPECT_NEAR(miss.twin.x, 0.5 * miss.gpu.x, 1e-6);
  auto nan = define("hold_nan", lambert, [](double nl) { return glm::dvec3(std::sqrt(nl)) * double(nl >= 0); });
  miss = hold_twin(nan, hold_light());
  ASSERT_TRUE(miss.failed);
  EXPECT_LT(glm::dot(miss.at.n, miss.at.l), 0.0);
  EXPECT_TRUE(std::isnan(miss.twin.x));
  auto right = define("hold_right", lambert, [](double nl) { return glm::dvec3(std::max(nl, 0.0)); });
  EXPECT_FALSE(hold_twin(right, hold_light()).failed);
  auto toon = define("hold_toon", "vec3 shade(Surface s, Params p) { return vec3(dot(s.n, s.l) > 0.5 ? 1.0 : 0.2); }",
                     [](double nl) { return glm::dvec3(nl > 0.5 ? 1.0 : 0.2); });
  EXPECT_FALSE(hold_twin(toon, hold_light()).failed);
}

// Without the guards the same grid does produce NaN: normalising a zero vector and a GGX lobe at
// alpha = 0 are what the guards exist for.
TEST(LightingStress, UnguardedFormulasWouldFailOnThisGrid) {
  glm::dvec3 zero(0.0);
  EXPECT_TRUE(std::isnan(glm::normalize(zero).x));
  EXPECT_EQ(safe_normalize(zero), zero);
  double a = 0.0, nh = 1.0, d = nh * nh * (a * a - 1) + 1;  // the textbook D at alpha = 0, n = h
  EXPECT_TRUE(std::isnan(a * a / (kPi * d * d)));
  EXPECT_TRUE(std::isfinite(ggx_distribution({0, 0, 1}, {0, 0, 1}, kMinAlpha)));
}

}  // namespace

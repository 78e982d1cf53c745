// The lighting models' CPU twin on its own: values the formulas fix exactly, physical identities
// (GGX's D integrates to 1 over projected solid angle, Smith's G2 <= 1, Fresnel's limits), where
// the highlights sit, and every parameter error.
#include <gtest/gtest.h>

#include <cmath>

#include "shading/lighting.h"

namespace {

using namespace sn::shading;
using sn::scene::Light;
using sn::scene::make_light;
using glm::dvec3;

const Light kLightUp = make_light({0, 1, 0}, {1, 1, 1});

TEST(Lighting, PhongAtNormalIncidenceIsColorPlusSpecular) {
  // n = l = v: cos(i) = 1 and r = v, so S_p = C_p (1 - d + d) + W.
  auto p = make_params("phong", {{"color", {0.2, 0.4, 0.6}}, {"ambient", {0.3}}, {"specular", {0.5}},
                                      {"shininess", {20}}});
  dvec3 s = shade_raw(p, kLightUp, {0, 1, 0}, {0, 1, 0});
  EXPECT_NEAR(s.r, 0.7, 1e-15);
  EXPECT_NEAR(s.g, 0.9, 1e-15);
  EXPECT_NEAR(s.b, 1.1, 1e-15);
  EXPECT_EQ(shade(p, kLightUp, {0, 1, 0}, {0, 1, 0}).b, 1.0);  // recorded value clamps
}

TEST(Lighting, PhongMatchesTheThesisFormulaAtAnAngle) {
  // S_p = C_p [cos(i)(1 - d) + d] + W cos(s)^n with i = 60 deg and s = 30 deg.
  auto p = make_params("phong", {{"color", {1}}, {"ambient", {0.1}}, {"specular", {0.5}}, {"shininess", {8}}});
  double i = kPi / 3;
  dvec3 n(0, 1, 0);
  Light light = make_light({std::sin(i), std::cos(i), 0}, {1, 1, 1});
  dvec3 r(-std::sin(i), std::cos(i), 0);  // mirror of l about n
  double s_angle = kPi / 6;
  dvec3 v = glm::normalize(std::cos(s_angle) * r + std::sin(s_angle) * dvec3(0, 0, 1));
  double expect = (std::cos(i) * 0.9 + 0.1) + 0.5 * std::pow(std::cos(s_angle), 8);
  EXPECT_NEAR(shade_raw(p, light, n, v).r, expect, 1e-12);
}

TEST(Lighting, PhongHighlightSitsOnTheMirrorDirection) {
  auto p = default_params("phong");
  Light light = make_light({1, 1, 0}, {1, 1, 1});
  dvec3 n(0, 1, 0), mirror = glm::normalize(dvec3(-1, 1, 0));
  double peak = shade_raw(p, light, n, mirror).r;
  for (double off : {0.05, -0.05})
    EXPECT_LT(shade_raw(p, light, n, glm::normalize(mirror + dvec3(0, 0, off))).r, peak);
  // No highlight from a light behind the surface.
  EXPECT_NEAR(shade_raw(p, make_light({0, -1, 0}, {1, 1, 1}), n, n).r, 0.8 * 0.1, 1e-15);
}

TEST(Lighting, BlinnPhongPeaksWhereTheHalfVectorIsTheNormal) {
  auto p = make_params("blinn_phong", {{"shininess", {50}}, {"specular", {1}}});
  Light light = make_light({1, 1, 0}, {1, 1, 1});
  dvec3 n(0, 1, 0), v = glm::normalize(dvec3(-1, 1, 0));  // h = n
  EXPECT_NEAR(shade_raw(p, light, n, v).r, 0.8 * (std::cos(kPi / 4) * 0.9 + 0.1) + 1.0, 1e-12);
  // v = -l: the half vector is undefined, so no highlight; still finite.
  dvec3 s = shade_raw(p, light, n, -light.dir);
  EXPECT_NEAR(s.r, 0.8 * (std::cos(kPi / 4) * 0.9 + 0.1), 1e-12);
}

// D is normalised: the integral of D(h) (n.h) over the hemisphere of h is 1.
TEST(Lighting, GgxDistributionIntegratesToOne) {
  for (double alpha : {0.1, 0.3, 0.7, 1.0}) {
    const int nt = 4000, np = 8;  // D is isotropic: the azimuth integral is exact with few points
    double sum = 0;
    for (int i = 0; i < nt; ++i) {
      double t = (i + 0.5) * (kPi / 2) / nt;
      dvec3 h(std::sin(t), std::cos(t), 0);
      sum += ggx_distribution({0, 1, 0}, h, alpha) * std::cos(t) * std::sin(t) * (kPi / 2 / nt) * 2 * kPi;
    }
    (void)np;
    EXPECT_NEAR(sum, 1.0, 2e-3) << "alpha " << alpha;
  }
  // The peak value 1 / (pi alpha^2).
  EXPECT_NEAR(ggx_distribution({0, 1, 0}, {0, 1, 0}, 0.5), 1 / (kPi * 0.25), 1e-12);
}

TEST(Lighting, SmithHeightCorrelatedVisibilityMatchesClosedFormAndBoundsG2) {
  double a = 0.4, nl = 0.6, nv = 0.8, a2 = a * a;
  double lambda_v = (-1 + std::sqrt(1 + a2 * (1 - nv * nv) / (nv * nv))) / 2;
  double lambda_l = (-1 + std::sqrt(1 + a2 * (1 - nl * nl) / (nl * nl))) / 2;
  double g2 = 1 / (1 + lambda_v + lambda_l);  // Heitz 2014, eq. 99
  EXPECT_NEAR(smith_visibility_nl(nl, nv, a), g2 / (4 * nl * nv) * nl, 1e-12);
  for (double x : {1e-7, 0.01, 0.3, 1.0})
    for (double y : {1e-7, 0.01, 0.3, 1.0}) EXPECT_LE(smith_visibility_nl(x, y, a) * 4 * y, 1.0 + 1e-12);
}

TEST(Lighting, SchlickFresnelLimits) {
  dvec3 gold(1.0, 0.71, 0.29);
  EXPECT_EQ(fresnel_schlick(gold, 1.0), gold);
  EXPECT_EQ(fresnel_schlick(gold, 0.0), dvec3(1.0));
  EXPECT_NEAR(fresnel_schlick(gold, 0.5).b, 0.29 + 0.71 * std::pow(0.5, 5), 1e-15);
}

TEST(Lighting, GgxGoldHighlightIsGoldAndSitsOnTheMirror) {
  auto p = make_params("ggx", {{"roughness", {0.3}}, {"ambient", {0}}});
  Light light = make_light({1, 1, 0}, {1, 1, 1});
  dvec3 n(0, 1, 0), mirror = glm::normalize(dvec3(-1, 1, 0));
  dvec3 peak = shade_raw(p, light, n, mirror);
  EXPECT_GT(peak.r, peak.g);
  EXPECT_GT(peak.g, peak.b);
  EXPECT_NEAR(peak.g / peak.r, 0.71, 1e-3);  // at the mirror v.h = n.v: F is nearly F0
  EXPECT_LT(shade_raw(p, light, n, glm::normalize(mirror + dvec3(0.3, 0, 0.3))).r, peak.r);
  // The formula: pi D V F n.l at h = n.
  double nl = std::sqrt(0.5), alpha = 0.09;
  double expect = kPi * (1 / (kPi * alpha * alpha)) * smith_visibility_nl(nl, nl, alpha) *
                  fresnel_schlick({1.0, 0.71, 0.29}, nl).r;
  EXPECT_NEAR(peak.r, expect, 1e-9 * expect);
  // Lit from below or seen from below: ambient only.
  auto q = make_params("ggx", {{"ambient", {0.1}}});
  EXPECT_EQ(shade_raw(q, light, {0, -1, 0}, mirror), 0.1 * dvec3(1.0, 0.71, 0.29));
}

TEST(Lighting, GgxWhiteLambertFacingTheLightReturnsTheLightColour) {
  auto p = make_params("ggx", {{"f0", {0}}, {"diffuse", {1}}, {"ambient", {0}}});
  Light light = make_light({0, 1, 0}, {0.3, 0.6, 0.9});
  dvec3 s = shade_raw(p, light, {0, 1, 0}, glm::normalize(dvec3(1, 1, 0)));
  // f0 = 0 leaves Schlick's (1 - v.h)^5 term; at v.h = cos(22.5 deg) it is ~1e-6.
  EXPECT_NEAR(s.r, 0.3, 1e-4);
  EXPECT_NEAR(s.b, 0.9, 1e-4);
}

TEST(Lighting, Toon3PicksTheThesisBands) {
  dvec3 a(0.1, 0.2, 0.3), d(0.5, 0.5, 0.5), s(1, 1, 1);
  glm::dvec4 t(0.2, 0.4, 0.6, 0.8);
  EXPECT_EQ(toon3(0.1, a, d, s, 0.25, t), a);
  EXPECT_EQ(toon3(0.3, a, d, s, 0.25, t), 0.75 * a + 0.25 * d);
  EXPECT_EQ(toon3(0.5, a, d, s, 0.25, t), d);
  EXPECT_EQ(toon3(0.7, a, d, s, 0.25, t), 0.75 * d + 0.25 * s);
  EXPECT_EQ(toon3(0.9, a, d, s, 0.25, t), s);
  EXPECT_EQ(toon3(0.2, a, d, s, 0.25, t), 0.75 * a + 0.25 * d);  // a threshold opens its band
  // The model: facing the light S_p = 1 + W = 1.5 > t4 -> the specular colour; from behind S_p = d.
  auto p = default_params("toon3");
  EXPECT_EQ(shade(p, kLightUp, {0, 1, 0}, {0, 1, 0}), dvec3(1.0, 0.95, 0.7));
  EXPECT_EQ(shade(p, kLightUp, {0, -1, 0}, {0, 1, 0}), dvec3(0.12, 0.1, 0.3));
}

TEST(Lighting, TexturedPhongMultipliesTheBaseColour) {
  auto p = make_params("textured_phong", {{"specular", {0}}, {"ambient", {0}}});
  dvec3 s = shade_raw(p, kLightUp, {0, 1, 0}, {0, 1, 0}, {0.25, 0.5, 1.0});
  EXPECT_EQ(s, dvec3(0.25, 0.5, 1.0));
}

TEST(Lighting, RawStaysWithinTheUpperBoundOnRandomInputs) {
  uint64_t x = 88172645463325252ull;
  auto rnd = [&] {
    x ^= x << 13, x ^= x >> 7, x ^= x << 17;
    return double(x >> 11) * 0x1p-53 * 2 - 1;
  };
  for (const auto& spec : models()) {
    auto p = make_params(spec, {});
    Light light = make_light({0.3, 0.8, -0.2}, {1, 1, 1});
    dvec3 b = upper_bound(p, light);
    for (int i = 0; i < 20000; ++i) {
      dvec3 s = shade_raw(p, light, {rnd(), rnd(), rnd()}, {rnd(), rnd(), rnd()}, {0.5 + 0.5 * rnd(), 1, 0});
      for (int c = 0; c < 3; ++c) {
        ASSERT_GE(s[c], 0.0) << spec->name;
        ASSERT_LE(s[c], b[c]) << spec->name;
      }
    }
  }
}

// ---- parameters ----

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

TEST(LightingParams, DefaultsAndDescribe) {
  auto p = default_params("ggx");
  EXPECT_EQ(p.scalar("roughness"), 0.3);
  EXPECT_EQ(p.color("f0"), dvec3(1.0, 0.71, 0.29));
  EXPECT_EQ(p.describe(), "ggx(roughness=0.3, f0={1, 0.71, 0.29}, diffuse={0, 0, 0}, ambient={0.1, 0.1, 0.1})");
  EXPECT_EQ(make_params("phong", {{"specular", {0.25}}}).color("specular"), dvec3(0.25));  // grey
}

TEST(LightingParams, KeyChangesWithEveryValue) {
  auto a = default_params("ggx");
  auto b = make_params("ggx", {{"roughness", {std::nextafter(0.3, 1.0)}}});
  EXPECT_NE(a.key(), b.key());
  EXPECT_EQ(a.key(), default_params("ggx").key());
  EXPECT_NE(default_params("phong").key(), default_params("blinn_phong").key());
}

TEST(LightingParams, ErrorsNameTheModelParameterAndDomain) {
  EXPECT_EQ(error_of([] { find_model("gxx"); }),
            "unknown lighting model 'gxx' (valid: phong, blinn_phong, ggx, toon3, textured_phong)");
  EXPECT_EQ(error_of([] { make_params("ggx", {{"rougness", {0.5}}}); }),
            "sn.lighting.ggx: unknown parameter 'rougness' (valid: roughness, f0, diffuse, ambient)");
  EXPECT_NE(error_of([] { make_params("ggx", {{"roughness", {-0.1}}}); })
                .find("parameter 'roughness' (perceptual roughness"),
            std::string::npos);
  EXPECT_NE(error_of([] { make_params("ggx", {{"roughness", {-0.1}}}); }).find("must lie in [0, 1], got -0.1"),
            std::string::npos);
  EXPECT_NE(error_of([] { make_params("phong", {{"color", {0.5, -0.2, 0.1}}}); })
                .find("must lie in [0, 1000], got {0.5, -0.2, 0.1}"),
            std::string::npos);
  EXPECT_NE(error_of([] { make_params("phong", {{"color", {0.5, 0.2}}}); })
                .find("3 numbers {r, g, b} or 1 number expected, got 2"),
            std::string::npos);
  EXPECT_EQ(error_of([] { make_params("toon3", {{"thresholds", {0.5, 0.3, 0.6, 0.9}}}); }),
            "sn.lighting.toon3 parameter 'thresholds' must be in order t1 <= t2 <= t3 <= t4, got {0.5, 0.3, 0.6, 0.9}");
  EXPECT_NE(error_of([] { make_params("phong", {{"shininess", {NAN}}}); }).find("must lie in [0, 1e+06]"),
            std::string::npos);
  EXPECT_NE(error_of([] { make_light({0, 0, 0}, {1, 1, 1}); }).find("non-zero, finite direction"), std::string::npos);
  EXPECT_NE(error_of([] { make_light({0, 1, 0}, {1, -1, 1}); }).find("light 'color' must lie in [0, 1000]"),
            std::string::npos);
  EXPECT_EQ(glm::length(make_light({3, 0, 4}, {1, 1, 1}).dir), 1.0);
}

}  // namespace

namespace {
TEST(LightingParams, TheDefaultLightIsUnitLength) {
  sn::scene::Light l;
  EXPECT_NEAR(glm::length(l.dir), 1.0, 1e-15);
  EXPECT_NEAR(l.dir.y, 0.7 / std::sqrt(1.1), 1e-15);
}
}  // namespace

// Datasets sampled from the lighting model's domain (runtime/data/sample.h): the directions are
// where the domains say, stratified far tighter than independent draws, the same for the same
// seed; the targets are the model's (GPU against the double twin); the cache answers repeats.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include "data/dataset_cache.h"
#include "data/sample.h"
#include "gl/context.h"
#include "io/hash.h"
#include "shading/color.h"
#include "shading/lighting.h"

namespace {

using namespace sn::data;
using glm::dvec3;


constexpr std::size_t kN = kThesisSamples;  // 64,149: not a power of two, on purpose

SampleRequest request(NormalDomain nd, ViewDomain vd, std::size_t n = kN, uint64_t seed = 1) {
  SampleRequest r;
  r.target = sn::shading::default_params("ggx");
  r.normals = nd;
  r.views = vd;
  r.n = n;
  r.seed = seed;
  return r;
}

dvec3 d(const glm::vec3& v) { return dvec3(v); }

// Rows per bucket; bucket(i) in [0, k).
template <class F>
std::vector<long> counts(std::size_t n, int k, F bucket) {
  std::vector<long> c(std::size_t(k), 0);
  for (std::size_t i = 0; i < n; ++i) ++c[std::size_t(bucket(i))];
  return c;
}

// The largest |count - n/k| over the buckets (printed: the margin below each bound shows).
double worst(const std::vector<long>& c, std::size_t n) {
  double w = 0, share = double(n) / double(c.size());
  for (long x : c) w = std::max(w, std::abs(double(x) - share));
  printf("%zu buckets of %.1f rows: worst off by %.1f\n", c.size(), share, w);
  return w;
}

int band(double x, double lo, double hi, int k) { return std::clamp(int((x - lo) / (hi - lo) * k), 0, k - 1); }

// Against long double libm, whose argument 2 pi t carries no double rounding.
TEST(DatasetSample, TurnCosSinIsCosAndSinOfTheTurn) {
  const long double two_pi = 6.283185307179586476925286766559L;
  double max_err = 0;
  for (int i = 0; i <= 100000; ++i) {
    const double t = i / 100001.0;
    const glm::dvec2 cs = turn_cos_sin(t);
    max_err = std::max({max_err, double(std::abs(cs.x - std::cos(two_pi * t))), double(std::abs(cs.y - std::sin(two_pi * t)))});
  }
  printf("max |turn_cos_sin - libm| = %.3g\n", max_err);
  EXPECT_LE(max_err, 2.5e-16);
  EXPECT_EQ(turn_cos_sin(0.0), glm::dvec2(1, 0));
  EXPECT_EQ(turn_cos_sin(0.25), glm::dvec2(0, 1));
  EXPECT_EQ(turn_cos_sin(0.5), glm::dvec2(-1, 0));
  EXPECT_EQ(turn_cos_sin(0.75), glm::dvec2(0, -1));
}

TEST(DatasetSample, SameSeedSameRowsOtherSeedOtherRows) {
  const SampleRequest r = request(NormalDomain::sphere, ViewDomain::uniform, 5000);
  const Directions a = sample_directions(r), b = sample_directions(r);
  ASSERT_EQ(a.normals.size(), 5000u);
  EXPECT_EQ(0, std::memcmp(a.normals.data(), b.normals.data(), a.normals.size() * sizeof(glm::vec3)));
  EXPECT_EQ(0, std::memcmp(a.views.data(), b.views.data(), a.views.size() * sizeof(glm::vec3)));

  const Directions c = sample_directions(request(NormalDomain::sphere, ViewDomain::uniform, 5000, 2));
  std::size_t same_n = 0, same_v = 0;
  for (std::size_t i = 0; i < 5000; ++i) same_n += a.normals[i] == c.normals[i], same_v += a.views[i] == c.views[i];
  EXPECT_EQ(same_n, 0u);
  EXPECT_EQ(same_v, 0u);
}

// The stream is part of the contract ("the same rows on any IEEE-754 machine"): these are the
// rows of seed 1 everywhere. A deliberate change of the sampler changes this number, and every
// sampled dataset with it; say so in the commit.
TEST(DatasetSample, RowsOfSeedOneArePinned) {
  const Directions a = sample_directions(request(NormalDomain::sphere, ViewDomain::cosine, 1000));
  sn::io::Fnv1a f;
  f.vec(a.normals);
  f.vec(a.views);
  EXPECT_EQ(f.h, 0xc32859a340663d07ull) << std::hex << f.h;
}

TEST(DatasetSample, EveryRowIsUnitFrontFacingAndInsideItsDomain) {
  SampleRequest tilted = request(NormalDomain::hemisphere, ViewDomain::cosine);
  tilted.axis = {1, -2, 0.5};  // any length: normalised
  SampleRequest lit = request(NormalDomain::lit, ViewDomain::uniform);
  lit.light = sn::scene::make_light({-0.3, 0.2, 0.9}, {1, 1, 1});
  for (const SampleRequest& r : {request(NormalDomain::sphere, ViewDomain::uniform),
                                 request(NormalDomain::hemisphere, ViewDomain::cosine), tilted, lit}) {
    const Directions s = sample_directions(r);
    ASSERT_EQ(s.normals.size(), kN);
    ASSERT_EQ(s.views.size(), kN);
    for (std::size_t i = 0; i < kN; ++i) {
      const dvec3 n = d(s.normals[i]), v = d(s.views[i]);
      ASSERT_NEAR(glm::length(n), 1.0, 1e-6) << i;
      ASSERT_NEAR(glm::length(v), 1.0, 1e-6) << i;
      ASSERT_GT(glm::dot(n, v), 0.0) << i;  // in the stored floats, not just before rounding
      ASSERT_GE(glm::dot(n, v), kMinCosView - 1e-6) << i;
      if (r.normals == NormalDomain::hemisphere && r.axis == dvec3(0, 1, 0)) ASSERT_GE(n.y, 0.0) << i;  // exactly
      if (r.normals == NormalDomain::hemisphere) ASSERT_GE(glm::dot(n, glm::normalize(r.axis)), -1e-7) << i;
      if (r.normals == NormalDomain::lit) ASSERT_GE(glm::dot(n, r.light.dir), -1e-7) << i;
    }
  }
}

// Stratification: an independent uniform draw of 64,149 rows puts n/k +- sqrt(n (1/k)(1 - 1/k))
// in each of k equal-area regions (about +-84 rows for octants); every bound below is a few rows.
TEST(DatasetSample, SphereNormalsFillEqualAreasWithinAFewRows) {
  const Directions s = sample_directions(request(NormalDomain::sphere, ViewDomain::uniform));
  const auto& n = s.normals;
  // Octants: 8018.6 rows each.
  auto oct = counts(kN, 8, [&](std::size_t i) { return (n[i].x > 0) + 2 * (n[i].y > 0) + 4 * (n[i].z > 0); });
  EXPECT_LE(worst(oct, kN), 3.0);
  // Equal-area bands of y (Archimedes: equal heights, equal areas), dyadic and not.
  for (int k : {2, 10, 64, 100}) {
    auto b = counts(kN, k, [&](std::size_t i) { return band(n[i].y, -1, 1, k); });
    EXPECT_LE(worst(b, kN), k <= 64 ? 4.0 : 6.0) << k << " bands";
  }
  // Wedges of longitude about y.
  auto w = counts(kN, 12, [&](std::size_t i) { return band(std::atan2(n[i].z, n[i].x), -M_PI, M_PI, 12); });
  EXPECT_LE(worst(w, kN), 6.0);
  // The cells of a 16 x 32 latitude-longitude equal-area grid (125 rows each; iid: +-11).
  auto g = counts(kN, 512, [&](std::size_t i) {
    return band(n[i].y, -1, 1, 16) * 32 + band(std::atan2(n[i].z, n[i].x), -M_PI, M_PI, 32);
  });
  EXPECT_LE(worst(g, kN), 6.0);
}

TEST(DatasetSample, HemisphereNormalsAreUniformOverTheUpperHalf) {
  const Directions s = sample_directions(request(NormalDomain::hemisphere, ViewDomain::uniform));
  const auto& n = s.normals;
  auto quad = counts(kN, 4, [&](std::size_t i) { return (n[i].x > 0) + 2 * (n[i].z > 0); });
  EXPECT_LE(worst(quad, kN), 3.0);
  auto b = counts(kN, 16, [&](std::size_t i) { return band(n[i].y, 0, 1, 16); });
  EXPECT_LE(worst(b, kN), 4.0);
  double mean_y = 0;
  for (auto& x : n) mean_y += x.y;
  printf("mean y %.8f\n", mean_y / kN);
  EXPECT_NEAR(mean_y / kN, 0.5, 3e-5);  // iid: +-1.1e-3
}

TEST(DatasetSample, UniformViewsAreUniformAboutTheNormal) {
  const Directions s = sample_directions(request(NormalDomain::sphere, ViewDomain::uniform));
  std::vector<double> c(kN);
  double mean = 0;
  for (std::size_t i = 0; i < kN; ++i) mean += c[i] = glm::dot(d(s.normals[i]), d(s.views[i]));
  mean /= kN;
  printf("mean n.v %.8f\n", mean);
  EXPECT_NEAR(mean, 0.5, 3e-5);  // uniform over the hemisphere: E[cos] = 1/2 (iid: +-1.1e-3)
  // Equal bands of cos are equal solid angles.
  auto b = counts(kN, 16, [&](std::size_t i) { return band(c[i], 0, 1, 16); });
  EXPECT_LE(worst(b, kN), 4.0);
  // The azimuth about the normal, in a frame of the test's own (x projected onto the tangent
  // plane): uniform, though not stratified in this frame, so the bound is iid's 4 sigma.
  auto a = counts(kN, 4, [&](std::size_t i) {
    const dvec3 n = d(s.normals[i]), v = d(s.views[i]);
    dvec3 ref = std::abs(n.x) < 0.9 ? dvec3(1, 0, 0) : dvec3(0, 0, 1);
    const dvec3 t = glm::normalize(ref - glm::dot(ref, n) * n), b2 = glm::cross(n, t);
    return band(std::atan2(glm::dot(v, b2), glm::dot(v, t)), -M_PI, M_PI, 4);
  });
  EXPECT_LE(worst(a, kN), 4 * std::sqrt(kN * 3.0 / 16));
}

TEST(DatasetSample, CosineViewsFollowTheCosineLobe) {
  const Directions s = sample_directions(request(NormalDomain::sphere, ViewDomain::cosine));
  std::vector<double> c(kN);
  double mean = 0;
  for (std::size_t i = 0; i < kN; ++i) mean += c[i] = glm::dot(d(s.normals[i]), d(s.views[i]));
  mean /= kN;
  printf("mean n.v %.8f\n", mean);
  EXPECT_NEAR(mean, 2.0 / 3.0, 3e-5);  // density cos/pi: E[cos] = 2/3 (iid: +-0.9e-3)
  // sin^2 = 1 - cos^2 is uniform under the lobe: equal bands of it hold equal rows.
  auto b = counts(kN, 16, [&](std::size_t i) { return band(1 - c[i] * c[i], 0, 1, 16); });
  EXPECT_LE(worst(b, kN), 4.0);
}

TEST(DatasetSample, SplitKeepsEveryRowOnce) {
  sn::gl::current();
  SampleRequest r = request(NormalDomain::sphere, ViewDomain::uniform, 1000);
  r.split = 0.8;
  auto ds = sample_dataset(r);
  EXPECT_EQ(ds->train_count(), 800u);
  EXPECT_EQ(ds->val_count(), 200u);
  EXPECT_EQ(ds->inputs, 6);
  EXPECT_EQ(ds->outputs, 3);
  EXPECT_EQ(ds->input_names, (std::vector<std::string>{"normal", "view"}));
  // Training and validation rows together are sample_directions' rows, each once.
  const Directions s = sample_directions(r);
  std::vector<std::vector<float>> want, got;
  for (std::size_t i = 0; i < r.n; ++i) {
    const auto &n = s.normals[i], &v = s.views[i];
    want.push_back({n.x, n.y, n.z, v.x, v.y, v.z});
  }
  for (auto* x : {&ds->train_x, &ds->val_x})
    for (std::size_t i = 0; i < x->size(); i += 6) got.emplace_back(x->begin() + i, x->begin() + i + 6);
  std::sort(want.begin(), want.end());
  std::sort(got.begin(), got.end());
  EXPECT_EQ(want, got);

  r.n = kN;
  auto big = sample_dataset(r);
  EXPECT_EQ(big->train_count(), 51319u);  // round(0.8 * 64149)
  EXPECT_EQ(big->val_count(), 12830u);
}

// Every target against the double-precision twin shading::shade of the same float inputs, within
// 1e-5 per channel (the lighting twin test's bound); rows within 1e-4 of a branch of the model
// (n.l = 0, n.v = 0) are skipped, where float may take the other side.
void expect_targets_match_twin(const std::string& m, sn::shading::ColorSpace color, NormalDomain nd, ViewDomain vd,
                               std::size_t rows = 20000) {
  sn::gl::current();
  SampleRequest r = request(nd, vd, rows, 7);
  std::map<std::string, std::vector<double>> params;
  if (m == "ggx") params = {{"roughness", {0.3}}, {"f0", {1.0, 0.71, 0.29}}, {"diffuse", {0.2, 0.1, 0.05}}};
  if (m == "phong") params = {{"shininess", {40}}};
  r.target = sn::shading::make_params(m, params);
  r.light = sn::scene::make_light({0.5, 0.7, 0.6}, {1, 0.9, 0.8});
  r.light.dir = dvec3(glm::vec3(r.light.dir));  // the GPU gets float(dir); so does the twin
  r.color = color;
  auto ds = sample_dataset(r);
  int compared = 0, skipped = 0;
  double max_err = 0;
  for (int set = 0; set < 2; ++set) {
    const auto& x = set ? ds->val_x : ds->train_x;
    const auto& y = set ? ds->val_y : ds->train_y;
    for (std::size_t i = 0; i < y.size() / 3; ++i) {
      const dvec3 n(x[i * 6], x[i * 6 + 1], x[i * 6 + 2]), v(x[i * 6 + 3], x[i * 6 + 4], x[i * 6 + 5]);
      if (sn::shading::near_discontinuity(r.target, r.light, n, v, 1e-4)) {
        ++skipped;
        continue;
      }
      const dvec3 twin = sn::shading::encode_color(color, sn::shading::shade(r.target, r.light, n, v));
      for (int c = 0; c < 3; ++c) {
        const double e = std::abs(double(y[i * 3 + c]) - twin[c]);
        max_err = std::max(max_err, e);
        ASSERT_LE(e, 1e-5) << r.target.describe() << " row " << i << " channel " << c;
      }
      ++compared;
    }
  }
  printf("[ %s ] %d rows compared, %d near a branch skipped, max |gpu - twin| = %.3g\n",
         m.c_str(), compared, skipped, max_err);
  EXPECT_LT(skipped, int(rows / 50));
  EXPECT_EQ(std::size_t(compared + skipped), rows);
  EXPECT_GT(max_err, 0.0);  // the GPU really ran
}

TEST(DatasetSample, PhongTargetsMatchTheTwin) {
  expect_targets_match_twin("phong", sn::shading::ColorSpace::rgb, NormalDomain::sphere, ViewDomain::uniform);
}
TEST(DatasetSample, GgxTargetsMatchTheTwin) {
  expect_targets_match_twin("ggx", sn::shading::ColorSpace::rgb, NormalDomain::hemisphere, ViewDomain::cosine);
}
TEST(DatasetSample, GgxTargetsMatchTheTwinInXyz) {
  expect_targets_match_twin("ggx", sn::shading::ColorSpace::cie_xyz, NormalDomain::lit, ViewDomain::uniform);
}

// The GPU shades 2^20 rows at a time: rows of the second, partial chunk must be theirs too.
TEST(DatasetSample, RowsPastTheFirstGpuChunkAreShaded) {
  expect_targets_match_twin("phong", sn::shading::ColorSpace::rgb, NormalDomain::sphere, ViewDomain::uniform,
                            (std::size_t(1) << 20) + 4097);
}

TEST(DatasetSample, BadRequestsAreRefusedWithReasons) {
  auto message = [](const SampleRequest& r) {
    try {
      validate(r);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  SampleRequest r = request(NormalDomain::sphere, ViewDomain::uniform, 100);
  EXPECT_EQ(message(r), "(accepted)");
  SampleRequest t = r;
  t.target = sn::shading::default_params("textured_phong");
  EXPECT_NE(message(t).find("textured_phong"), std::string::npos);
  EXPECT_NE(message(t).find("scene:dataset"), std::string::npos);
  for (std::size_t n : {std::size_t(0), std::size_t(1), kMaxSampleRows + 1}) {
    SampleRequest b = r;
    b.n = n;
    EXPECT_NE(message(b).find("a sampled dataset has 2..16777216 rows, not "), std::string::npos) << n;
  }
  for (double split : {0.0, 1.0, -0.5, std::nan("")}) {
    SampleRequest b = r;
    b.split = split;
    EXPECT_NE(message(b).find("strictly between 0 and 1"), std::string::npos) << split;
  }
  for (dvec3 axis : {dvec3(0), dvec3(std::nan(""), 1, 0), dvec3(INFINITY, 0, 0)}) {
    SampleRequest b = r;
    b.normals = NormalDomain::hemisphere;
    b.axis = axis;
    EXPECT_NE(message(b).find("axis must be a non-zero, finite direction"), std::string::npos);
  }
  SampleRequest tiny = r;
  tiny.n = 1;
  EXPECT_THROW(sample_directions(tiny), std::invalid_argument);
  try {
    parse_normal_domain("cube");
    ADD_FAILURE();
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "unknown normals domain 'cube' (valid: sphere, hemisphere, lit)");
  }
  try {
    parse_view_domain("sphere");
    ADD_FAILURE();
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "unknown views domain 'sphere' (valid: uniform, cosine)");
  }
  EXPECT_EQ(parse_normal_domain("lit"), NormalDomain::lit);
  EXPECT_EQ(parse_view_domain("cosine"), ViewDomain::cosine);
}

TEST(DatasetSample, KeyCoversEveryPartOfTheRequest) {
  const SampleRequest base = request(NormalDomain::hemisphere, ViewDomain::uniform, 1000);
  const std::string k0 = sample_key(base);
  EXPECT_EQ(k0.substr(0, 7), "sample\n");  // never a scene dataset's key
  std::vector<std::pair<const char*, SampleRequest>> changes;
  auto change = [&](const char* what, auto edit) {
    SampleRequest r = base;
    edit(r);
    changes.push_back({what, r});
  };
  change("model parameter", [](SampleRequest& r) { r.target = sn::shading::make_params("ggx", {{"roughness", {0.31}}}); });
  change("model", [](SampleRequest& r) { r.target = sn::shading::default_params("phong"); });
  change("light dir", [](SampleRequest& r) { r.light = sn::scene::make_light({0.5, 0.7, 0.61}, {1, 1, 1}); });
  change("light colour", [](SampleRequest& r) { r.light.color = {1, 1, 0.9}; });
  change("n", [](SampleRequest& r) { r.n = 1001; });
  change("normals", [](SampleRequest& r) { r.normals = NormalDomain::sphere; });
  change("views", [](SampleRequest& r) { r.views = ViewDomain::cosine; });
  change("axis", [](SampleRequest& r) { r.axis = {0, 1, 1e-9}; });
  change("seed", [](SampleRequest& r) { r.seed = 2; });
  change("split", [](SampleRequest& r) { r.split = 0.75; });
  change("colour", [](SampleRequest& r) { r.color = sn::shading::ColorSpace::hsv; });
  for (auto& [what, r] : changes) EXPECT_NE(sample_key(r), k0) << what;
  // The axis is a direction: its length is not part of the request.
  SampleRequest longer = base;
  longer.axis = {0, 3, 0};
  EXPECT_EQ(sample_key(longer), k0);
}

TEST(DatasetSample, AnIdenticalRequestIsACacheHit) {
  sn::gl::current();
  clear_dataset_cache();
  SampleRequest r = request(NormalDomain::sphere, ViewDomain::cosine, 3000, 11);
  const DatasetStats s0 = dataset_stats();
  auto a = cached_sample_dataset(r);
  const DatasetStats s1 = dataset_stats();
  EXPECT_EQ(s1.builds, s0.builds + 1);
  EXPECT_EQ(s1.hits, s0.hits);
  auto b = cached_sample_dataset(r);
  const DatasetStats s2 = dataset_stats();
  EXPECT_EQ(s2.builds, s1.builds);
  EXPECT_EQ(s2.hits, s1.hits + 1);
  EXPECT_EQ(a.get(), b.get());
  EXPECT_EQ(s2.gbuffer_renders, s0.gbuffer_renders);  // sampling renders nothing
  EXPECT_EQ(a->key.substr(0, 8), "dataset-");
  r.seed = 12;
  auto c = cached_sample_dataset(r);
  EXPECT_EQ(dataset_stats().builds, s2.builds + 1);
  EXPECT_NE(c->train_x, a->train_x);
  // Rebuilt after the cache is cleared: the same rows.
  r.seed = 11;
  clear_dataset_cache();
  auto d2 = cached_sample_dataset(r);
  EXPECT_NE(d2.get(), a.get());
  EXPECT_EQ(d2->train_x, a->train_x);
  EXPECT_EQ(d2->val_y, a->val_y);
}

}  // namespace

// Coverage bins: known directions land in the bins the scheme (data/coverage.h) promises, the
// bins are equal-area (uniform directions fill them evenly), and covered fractions and outside
// shares come out exactly on datasets built to have them.
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cmath>
#include <random>

#include "data/coverage.h"
#include "gl/context.h"
#include "scene/gather.h"
#include "scene/procedural.h"

namespace {

using namespace sn;
using data::BinScheme;

constexpr double kPi = 3.14159265358979323846;

int nbin(double x, double y, double z) { return data::normal_bin(BinScheme{}, x, y, z); }

int vbin(std::array<double, 3> n, std::array<double, 3> v) { return data::view_bin(BinScheme{}, n.data(), v.data()); }

// Default scheme: normal bin = band * 32 + sector (16 bands from y = -1), view bin = band * 32 +
// sector (8 bands from n.v = 0).
int nb(int band, int sector) { return band * 32 + sector; }

// A dataset of (normal, view) rows, all training rows.
data::Dataset rows_dataset(const std::vector<std::array<float, 6>>& rows) {
  data::Dataset d;
  d.inputs = 6, d.outputs = 3;
  d.input_names = {"normal", "view"};
  for (const auto& r : rows) {
    d.train_x.insert(d.train_x.end(), r.begin(), r.end());
    d.train_y.insert(d.train_y.end(), {0.f, 0.f, 0.f});
  }
  return d;
}

data::Histogram hist_of(const data::Dataset& d, const BinScheme& s = {}) {
  return data::histogram(data::dataset_directions(d, "test"), s);
}

// A uniformly random unit vector (a normalised Gaussian triple).
std::array<double, 3> random_direction(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  for (;;) {
    double a = g(rng), b = g(rng), c = g(rng), l = std::sqrt(a * a + b * b + c * c);
    if (l > 1e-9) return {a / l, b / l, c / l};
  }
}

}  // namespace

TEST(Coverage, NormalsAtPolesAndEquatorLandInTheirBins) {
  EXPECT_EQ(nbin(0, 1, 0), nb(15, 0));    // +y: top band; phi = atan2(0, 0) = 0
  EXPECT_EQ(nbin(0, -1, 0), nb(0, 0));    // -y: bottom band
  EXPECT_EQ(nbin(1, 0, 0), nb(8, 0));     // y = 0 opens band 8; phi = 0
  EXPECT_EQ(nbin(0, 0, 1), nb(8, 8));     // phi = 90 degrees
  EXPECT_EQ(nbin(-1, 0, 0), nb(8, 16));   // phi = 180
  EXPECT_EQ(nbin(0, 0, -1), nb(8, 24));   // phi = 270
  EXPECT_EQ(nbin(0, 0.999, 0.01), nb(15, 8));
  EXPECT_EQ(nbin(0.6, -0.8, 0), nb(1, 0));  // y = -0.8 is in [-0.875, -0.75)
  // Length does not matter: the direction is binned.
  EXPECT_EQ(nbin(0, 0, 5), nbin(0, 0, 1));
  EXPECT_EQ(nbin(0, 0, 0), -1);
  EXPECT_EQ(nbin(NAN, 0, 1), -1);
  EXPECT_EQ(nbin(INFINITY, 0, 1), -1);
}

TEST(Coverage, PhiWrapsAroundAtPlusX) {
  EXPECT_EQ(nbin(1, 0, 1e-3), nb(8, 0));    // just past 0
  EXPECT_EQ(nbin(1, 0, -1e-3), nb(8, 31));  // just below 360
  EXPECT_EQ(nbin(1, 0, -1e-12), nb(8, 31));
  EXPECT_EQ(nbin(-1, 0, 1e-12), nb(8, 15));   // just below 180
  EXPECT_EQ(nbin(-1, 0, -1e-12), nb(8, 16));  // just past 180 (atan2 gives -180 + e: wrapped)
}

TEST(Coverage, ViewsInTheNormalsFrame) {
  // Normal +x: t = world +y (already in the tangent plane), b = n x t = +z.
  const std::array<double, 3> n{1, 0, 0};
  EXPECT_EQ(vbin(n, {1, 0, 0}), 7 * 32 + 0);       // along the normal: top band
  EXPECT_EQ(vbin(n, {0.05, 1, 0}), 0 * 32 + 0);     // grazing, towards +y
  EXPECT_EQ(vbin(n, {0.05, 0, 1}), 0 * 32 + 8);     // grazing, towards b = +z: psi = 90
  EXPECT_EQ(vbin(n, {0.05, -1, 0}), 0 * 32 + 16);   // psi = 180
  EXPECT_EQ(vbin(n, {0.05, 0, -1}), 0 * 32 + 24);   // psi = 270
  EXPECT_EQ(vbin(n, {0.05, 1, -1e-3}), 0 * 32 + 31);  // azimuth wraps at t
  EXPECT_EQ(vbin(n, {0.5, 0.8660254, 0}), 4 * 32);    // n.v = 0.5 opens band 4
  EXPECT_EQ(vbin(n, {0.49, 0.871, 0}), 3 * 32);
  EXPECT_EQ(vbin(n, {1e-9, 1, 0}), 0);               // the most grazing view still has a bin
  EXPECT_EQ(vbin(n, {0, 1, 0}), -1);                 // in the tangent plane: below the horizon
  EXPECT_EQ(vbin(n, {-1, 0, 0}), -1);
  EXPECT_EQ(vbin(n, {0, 0, 0}), -1);
  // Normal +y: +y has no projection, so t = world +z and b = n x t = +x.
  const std::array<double, 3> up{0, 1, 0};
  EXPECT_EQ(vbin(up, {0, 0.1, 1}), 0 * 32 + 0);
  EXPECT_EQ(vbin(up, {1, 0.1, 0}), 0 * 32 + 8);
  EXPECT_EQ(vbin({0, -1, 0}, {0, -0.1, 1}), 0 * 32 + 0);
  // Just off the pole (beyond 1e-6) the projected +y rules again: it points away from the tilt.
  const std::array<double, 3> tilted{1e-4, 1, 0};
  EXPECT_EQ(vbin(tilted, {-1, 0.1, 0}), 0 * 32 + 0);
  // Inside 1e-6 of the pole the frame stays the +z one, never NaN.
  EXPECT_EQ(vbin({1e-8, 1, 0}, {0.1, 0.1, 1}), 0 * 32 + 0);
}

TEST(Coverage, BinsHaveEqualSolidAngle) {
  const BinScheme s;
  EXPECT_NEAR(data::normal_bin_solid_angle(s), 4 * kPi / 512, 1e-15);
  EXPECT_NEAR(data::view_bin_solid_angle(s), 2 * kPi / 256, 1e-15);
  // Uniform random directions fill equal-area bins evenly: counts are Poisson around the mean,
  // so a chi-square over the bins stays near its degrees of freedom. (Bands uniform in theta
  // instead of cos(theta) would put ~8x fewer rows in the polar bins and fail by thousands.)
  std::mt19937_64 rng(7);
  const int per_bin = 400;
  std::vector<int> normal(512), view(256);
  for (int i = 0; i < 512 * per_bin; ++i) {
    auto n = random_direction(rng);
    normal[std::size_t(nbin(n[0], n[1], n[2]))]++;
  }
  for (int i = 0; i < 256 * per_bin; ++i) {
    auto n = random_direction(rng), v = random_direction(rng);
    const double c = n[0] * v[0] + n[1] * v[1] + n[2] * v[2];
    if (c == 0) continue;
    if (c < 0) v = {-v[0], -v[1], -v[2]};  // a uniform direction on n's hemisphere
    view[std::size_t(data::view_bin(s, n.data(), v.data()))]++;
  }
  for (auto* counts : {&normal, &view}) {
    double chi2 = 0;
    for (int c : *counts) {
      chi2 += double(c - per_bin) * (c - per_bin) / per_bin;
      EXPECT_NEAR(c, per_bin, 6 * std::sqrt(per_bin));
    }
    const double dof = double(counts->size() - 1);
    EXPECT_LT(chi2, dof + 6 * std::sqrt(2 * dof));
    EXPECT_GT(chi2, dof - 6 * std::sqrt(2 * dof));
  }
}

TEST(Coverage, UpperHemisphereCoversHalfTheNormals) {
  std::mt19937_64 rng(3);
  std::vector<std::array<float, 6>> rows;
  for (int i = 0; i < 100000; ++i) {
    auto n = random_direction(rng);
    if (n[1] <= 0) n[1] = -n[1];
    if (n[1] == 0) continue;
    rows.push_back({float(n[0]), float(n[1]), float(n[2]), float(n[0]), float(n[1]), float(n[2])});
  }
  const auto h = hist_of(rows_dataset(rows));
  EXPECT_EQ(h.rows, rows.size());
  EXPECT_EQ(data::covered_bins(h.normal, 1), 256u);  // every upper bin, no lower one
  for (int b = 0; b < 256; ++b) EXPECT_EQ(h.normal[std::size_t(b)], 0u) << "lower bin " << b;
  EXPECT_GT(h.normal_y_min, 0);
  EXPECT_LE(h.normal_y_max, 1);
  // v = n: every view is in the top band (its azimuth is rounding noise: any of the band's sectors).
  std::size_t top = 0;
  for (int s = 0; s < 32; ++s) top += h.view[std::size_t(7 * 32 + s)];
  EXPECT_EQ(top, rows.size());
}

TEST(Coverage, OutsideSharesOfConstructedRows) {
  // Mine: upper normals seen head-on. Other: four equal groups, in / normal out / view out / both.
  const float r = 0.70710678f;
  auto mine = hist_of(rows_dataset({{0, 1, 0, 0, 1, 0}, {r, r, 0, r, r, 0}}));
  std::vector<std::array<float, 6>> other;
  for (int i = 0; i < 5; ++i) {
    other.push_back({0, 1, 0, 0, 1, 0});             // covered normal and view
    other.push_back({0, -1, 0, 0, -1, 0});           // lower normal; head-on view (covered)
    other.push_back({0, 1, 0, 0, 0.05f, 1});         // covered normal; grazing view
    other.push_back({0, -1, 0, 0, -0.05f, 1});       // both outside
  }
  const auto od = rows_dataset(other);
  const auto o = data::outside(mine, 1, data::dataset_directions(od, "other"));
  EXPECT_EQ(o.rows, 20u);
  EXPECT_DOUBLE_EQ(o.normal, 0.5);
  EXPECT_DOUBLE_EQ(o.view, 0.5);
  EXPECT_DOUBLE_EQ(o.either, 0.75);
  // Against itself nothing is outside.
  const auto self = data::outside(data::histogram(data::dataset_directions(od, "o"), {}), 1,
                                  data::dataset_directions(od, "o"));
  EXPECT_DOUBLE_EQ(self.either, 0.0);
}

TEST(Coverage, MinCountDecidesWhatIsCovered) {
  // Two rows in the +y bin, one in the +x bin.
  auto d = rows_dataset({{0, 1, 0, 0, 1, 0}, {0, 1, 0, 0, 1, 0}, {1, 0, 0, 1, 0, 0}});
  const auto h = hist_of(d);
  EXPECT_EQ(data::covered_bins(h.normal, 1), 2u);
  EXPECT_EQ(data::covered_bins(h.normal, 2), 1u);
  EXPECT_EQ(data::covered_bins(h.normal, 3), 0u);
  auto probe = rows_dataset({{1, 0, 0, 1, 0, 0}});
  EXPECT_DOUBLE_EQ(data::outside(h, 1, data::dataset_directions(probe, "p")).normal, 0.0);
  EXPECT_DOUBLE_EQ(data::outside(h, 2, data::dataset_directions(probe, "p")).normal, 1.0);
  EXPECT_THROW(data::outside(h, 0, data::dataset_directions(probe, "p")), std::invalid_argument);
}

TEST(Coverage, InvalidNonUnitAndBelowHorizonRows) {
  auto d = rows_dataset({{0, 0, 0, 0, 1, 0},         // zero normal: invalid
                         {0, 1, 0, 0, 0, 0},         // zero view: invalid
                         {0, 3, 0, 0, 2, 0},         // long vectors: binned by direction
                         {1, 0, 0, -1, 0.1f, 0},     // n.v < 0: normal binned, no view bin
                         {0, 1, 0, 0, 1, 0}});
  d.val_x = {NAN, 0, 1, 0, 0, 1};  // NaN normal in a validation row: invalid
  d.val_y = {0, 0, 0};
  const auto h = hist_of(d);
  EXPECT_EQ(h.rows, 6u);
  EXPECT_EQ(h.invalid, 3u);
  EXPECT_EQ(h.non_unit, 2u);  // the long pair, and the below-horizon view of length 1.005
  EXPECT_EQ(h.below_horizon, 1u);
  EXPECT_EQ(h.normal[std::size_t(nb(15, 0))], 2u);
  EXPECT_EQ(h.normal[std::size_t(nb(8, 0))], 1u);
  EXPECT_EQ(h.view[7 * 32], 2u);
  std::size_t binned = 0;
  for (uint32_t c : h.view) binned += c;
  EXPECT_EQ(binned, 2u);
  // Another set's below-horizon view is outside unless this one has such views too.
  auto probe = rows_dataset({{1, 0, 0, -1, 0.1f, 0}});
  EXPECT_DOUBLE_EQ(data::outside(h, 1, data::dataset_directions(probe, "p")).view, 0.0);
  EXPECT_DOUBLE_EQ(data::outside(h, 2, data::dataset_directions(probe, "p")).view, 1.0);
  // Nothing usable to measure: an error, not 0 / 0.
  auto junk = rows_dataset({{0, 0, 0, 0, 0, 0}});
  EXPECT_THROW(data::outside(h, 1, data::dataset_directions(junk, "j")), std::invalid_argument);
}

TEST(Coverage, InputsAreFoundWhereverTheyAre) {
  // uv (2), view (3), normal (3): view at column 2, normal at column 5.
  data::Dataset d;
  d.inputs = 8, d.outputs = 3;
  d.input_names = {"uv", "view", "normal"};
  d.train_x = {0.5f, 0.5f, 1, 0, 0, 0, 1, 0};
  d.train_y = {0, 0, 0};
  const auto h = hist_of(d);
  EXPECT_EQ(h.normal[std::size_t(nb(15, 0))], 1u);
  EXPECT_EQ(h.below_horizon, 1u);  // n = +y, v = +x: in the tangent plane

  data::Dataset p = d;
  p.input_names = {"uv", "position", "normal"};
  try {
    data::dataset_directions(p, "ds:coverage");
    FAIL() << "no view input";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("ds:coverage: the dataset's inputs are {\"uv\", \"position\", \"normal\"}"),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("\"normal\" and \"view\""), std::string::npos) << e.what();
  }
  p.input_names.clear();
  EXPECT_THROW(data::dataset_directions(p, "x"), std::invalid_argument);
  p.input_names = {"normal", "view"};  // 6 numbers named, 8 held
  EXPECT_THROW(data::dataset_directions(p, "x"), std::invalid_argument);

  data::Dataset empty;
  empty.inputs = 6;
  empty.input_names = {"normal", "view"};
  EXPECT_THROW(hist_of(empty), std::invalid_argument);
}

TEST(Coverage, SchemeResolutionsAreChecked) {
  BinScheme s;
  s.normal_bands = 4, s.normal_sectors = 3, s.view_bands = 2, s.view_sectors = 5;
  EXPECT_EQ(data::normal_bin(s, 0, 1, 0), 3 * 3);
  EXPECT_EQ(data::normal_bin(s, 0, 0, -1), 2 * 3 + 2);  // phi = 270: sector 2 of 3
  auto d = rows_dataset({{0, 1, 0, 0, 1, 0}});
  const auto h = hist_of(d, s);
  EXPECT_EQ(h.normal.size(), 12u);
  EXPECT_EQ(h.view.size(), 10u);
  s.view_sectors = 0;
  EXPECT_THROW(hist_of(d, s), std::invalid_argument);
  s.view_sectors = data::kMaxDivisions + 1;
  EXPECT_THROW(hist_of(d, s), std::invalid_argument);
}

TEST(Coverage, BinningIsFast) {
  // 64k rows, the size of a thesis dataset, in milliseconds (generous: sanitizer builds too).
  std::mt19937_64 rng(5);
  std::vector<std::array<float, 6>> rows;
  for (int i = 0; i < 65536; ++i) {
    auto n = random_direction(rng), v = random_direction(rng);
    rows.push_back({float(n[0]), float(n[1]), float(n[2]), float(v[0]), float(v[1]), float(v[2])});
  }
  const auto d = rows_dataset(rows);
  const auto t0 = std::chrono::steady_clock::now();
  const auto h = hist_of(d);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(h.rows, 65536u);
  EXPECT_LT(ms, 500.0);
}

TEST(Coverage, FigureShowsWhatOnlyTheOtherHas) {
  // Mine: upper normals; other: all normals. The figure has red only when given the other.
  std::mt19937_64 rng(11);
  std::vector<std::array<float, 6>> up, all;
  for (int i = 0; i < 20000; ++i) {
    auto n = random_direction(rng);
    all.push_back({float(n[0]), float(n[1]), float(n[2]), float(n[0]), float(n[1]), float(n[2])});
    if (n[1] > 0) up.push_back(all.back());
  }
  const auto mine = hist_of(rows_dataset(up));
  const auto other = hist_of(rows_dataset(all));
  auto count = [](const io::Image& img, float r, float g, float b) {
    int n = 0;
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x)
        n += std::fabs(img.at(x, y, 0) - r) < 1e-6f && std::fabs(img.at(x, y, 1) - g) < 1e-6f &&
             std::fabs(img.at(x, y, 2) - b) < 1e-6f;
    return n;
  };
  data::CoverageFigure f;
  f.title = "test";
  const io::Image alone = data::coverage_figure(mine, nullptr, f);
  f.against = "the other";
  const io::Image both = data::coverage_figure(mine, &other, f);
  EXPECT_EQ(alone.width, both.width);
  EXPECT_EQ(alone.height, both.height);
  EXPECT_GE(alone.width, 1000);
  EXPECT_GE(alone.height, 400);
  // Half the normal map (576 x 288 px, bins outlined) is uncovered: grey alone, red with the other.
  const int half = 576 * 144;
  EXPECT_EQ(count(alone, 0.9f, 0.1f, 0.1f), 0);
  EXPECT_GT(count(alone, 0.8f, 0.8f, 0.8f), half * 3 / 4);
  EXPECT_GT(count(both, 0.9f, 0.1f, 0.1f), half * 3 / 4);
  EXPECT_LT(count(both, 0.8f, 0.8f, 0.8f), count(alone, 0.8f, 0.8f, 0.8f) - half * 3 / 4);
}

TEST(Coverage, SceneRowsAreItsCoveredPixels) {
  gl::current();
  scene::Scene s;
  s.meshes.push_back({std::make_shared<scene::Mesh>(scene::sphere(1.0, 64, 32))});
  s.width = 64, s.height = 48;
  s.views = scene::framing_orbit(s.bounds(), 3, 20);
  const std::vector<float> rows = data::scene_directions(s);
  ASSERT_EQ(rows.size() % 6, 0u);
  std::size_t covered = 0;
  for (int v = 0; v < 3; ++v) covered += scene::gather(s.gbuffer(v, {"normal"})).count;
  EXPECT_EQ(rows.size() / 6, covered);
  for (std::size_t i = 0; i < rows.size(); i += 6) {
    EXPECT_NEAR(std::hypot(rows[i], rows[i + 1], rows[i + 2]), 1.0, 1e-3);
    EXPECT_NEAR(std::hypot(rows[i + 3], rows[i + 4], rows[i + 5]), 1.0, 1e-3);
  }
  // A camera looking away covers nothing: an error, not an empty measurement.
  s.views = {scene::Camera{{0, 0, 5}, {0, 0, 10}}};
  EXPECT_THROW(data::scene_directions(s), std::invalid_argument);
}

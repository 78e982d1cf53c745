// SSIM against scikit-image 0.19.3 (Debian 12's python3-skimage): structural_similarity(a, b,
// gaussian_weights=True, sigma=1.5, use_sample_covariance=False, data_range=1.0, channel_axis=2)
// on the float32 images built below (40x28, 3 channels), printed with repr().
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "io/ssim.h"

namespace {

using sn::io::Image;

// kind 0: a plus a cosine ripple; 1: a darkened (0.8 a + 0.05); 2: a shifted, sheared pattern.
std::pair<Image, Image> pair(int kind, int w = 40, int h = 28) {
  Image a(w, h, 3), b(w, h, 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) {
        const double va = 0.5 + 0.4 * std::sin(0.3 * x + 0.2 * y + c);
        const double vb = kind == 0   ? va + 0.1 * std::cos(0.7 * x - 0.4 * y + 2 * c)
                          : kind == 1 ? 0.8 * va + 0.05
                                      : 0.5 + 0.4 * std::sin(0.3 * x + 0.25 * y + c + 0.5);
        a.at(x, y, c) = float(va), b.at(x, y, c) = float(vb);
      }
  return {a, b};
}

// Every vector path this CPU has (the filter in 2 or 8 doubles) gives scikit-image's values.
TEST(Ssim, MatchesScikitImage) {
  const double reference[] = {0.8793921326774964, 0.9705250907118232, 0.22787864961837564};
  for (int lanes : {2, 8}) {
    if (lanes > sn::io::ssim_widest_lanes()) continue;
    for (int k = 0; k < 3; ++k) {
      auto [a, b] = pair(k);
      EXPECT_NEAR(sn::io::ssim_lanes(lanes, a, b), reference[k], 1e-9) << "pair " << k << ", " << lanes << " lanes";
    }
  }
  std::printf("ssim filter paths tested here: 2 lanes%s\n", sn::io::ssim_widest_lanes() == 8 ? ", 8 lanes" : "");
}

TEST(Ssim, EqualImagesAreOneAndAFullMaskChangesNothing) {
  auto [a, b] = pair(0);
  EXPECT_NEAR(sn::io::ssim(a, a), 1.0, 1e-12);
  Image all(40, 28, 4, 1.f);
  EXPECT_EQ(sn::io::ssim(a, b, -1, &all, 3), sn::io::ssim(a, b));
  // A mask over the left half averages only there: a different number, still within (0, 1].
  Image left(40, 28, 4, 0.f);
  for (int y = 0; y < 28; ++y)
    for (int x = 0; x < 20; ++x) left.at(x, y, 3) = 1.f;
  const double half = sn::io::ssim(a, b, -1, &left, 3);
  EXPECT_NE(half, sn::io::ssim(a, b));
  EXPECT_GT(half, 0.0);
  EXPECT_LE(half, 1.0);
}

// The mean SSIM over the mask's interior pixels from plain 11x11 window sums (the oracle); `count`:
// how many pixels it averaged.
double direct_ssim(const Image& a, const Image& b, const Image& mask, int* count) {
  const int r = sn::io::kSsimRadius, w = a.width, h = a.height;
  double k[2 * sn::io::kSsimRadius + 1], ksum = 0;
  for (int d = -r; d <= r; ++d) ksum += k[d + r] = std::exp(-0.5 * d * d / (1.5 * 1.5));
  double want = 0;
  for (int c = 0; c < 3; ++c) {
    double sum = 0;
    *count = 0;
    for (int y = r; y < h - r; ++y)
      for (int x = r; x < w - r; ++x) {
        if (mask.at(x, y, 3) <= 0.5f) continue;
        double mx = 0, my = 0, xx = 0, yy = 0, xy = 0;
        for (int dy = -r; dy <= r; ++dy)
          for (int dx = -r; dx <= r; ++dx) {
            const double wgt = k[dx + r] * k[dy + r] / (ksum * ksum), u = a.at(x + dx, y + dy, c), v = b.at(x + dx, y + dy, c);
            mx += wgt * u, my += wgt * v, xx += wgt * u * u, yy += wgt * v * v, xy += wgt * u * v;
          }
        const double c1 = 1e-4, c2 = 9e-4;
        sum += (2 * mx * my + c1) * (2 * (xy - mx * my) + c2) /
               ((mx * mx + my * my + c1) * (xx - mx * mx + yy - my * my + c2));
        ++*count;
      }
    want += sum / *count / 3;
  }
  return want;
}

// A mask filters only around itself (its bounding box): the mean over a small blob must equal
// the same mean of per-pixel SSIMs from plain 11x11 window sums.
TEST(Ssim, AMaskedMeanMatchesDirectWindowSums) {
  auto [a, b] = pair(2);
  Image blob(40, 28, 4, 0.f);
  for (int y = 0; y < 28; ++y)
    for (int x = 0; x < 40; ++x)
      if ((x - 24) * (x - 24) + (y - 13) * (y - 13) <= 16) blob.at(x, y, 3) = 1.f;
  int count = 0;
  const double want = direct_ssim(a, b, blob, &count);
  ASSERT_EQ(count, 49);  // the blob: 49 pixels, all inside
  for (int lanes : {2, 8})
    if (lanes <= sn::io::ssim_widest_lanes()) EXPECT_NEAR(sn::io::ssim_lanes(lanes, a, b, -1, &blob, 3), want, 1e-12) << lanes;
  EXPECT_NE(sn::io::ssim(a, b, -1, &blob, 3), sn::io::ssim(a, b));
}

// A tall mask is filtered in bands of rows on several threads: still the direct sums' value,
// and the same number to the bit on one thread as on three.
TEST(Ssim, BandsOnThreadsGiveTheDirectValue) {
  auto [a, b] = pair(0, 48, 150);
  Image ring(48, 150, 4, 0.f);
  for (int y = 0; y < 150; ++y)
    for (int x = 0; x < 48; ++x) {
      const int d = (x - 22) * (x - 22) + (y - 70) * (y - 70) / 4;
      if (d >= 36 && d <= 300) ring.at(x, y, 3) = 1.f;
    }
  int count = 0;
  const double want = direct_ssim(a, b, ring, &count);
  ASSERT_GT(count, 1000);
  std::string was = std::getenv("SHADENET_THREADS") ? std::getenv("SHADENET_THREADS") : "";
  double got[2];
  for (int t : {0, 1}) {
    setenv("SHADENET_THREADS", t ? "3" : "1", 1);
    got[t] = sn::io::ssim(a, b, -1, &ring, 3);
    EXPECT_NEAR(got[t], want, 1e-12);
  }
  if (was.empty()) unsetenv("SHADENET_THREADS");
  else setenv("SHADENET_THREADS", was.c_str(), 1);
  EXPECT_EQ(got[0], got[1]);
}

// A reference prepared once (a truth view scored against many renders) gives each comparison
// the same number to the bit as ssim of the pair, on every vector path, masked or not, and the
// direct window sums' value (the oracle; ssim of a pair goes through a reference too).
TEST(Ssim, APreparedReferenceGivesEachPairsValueToTheBit) {
  Image ring(48, 150, 4, 0.f);
  for (int y = 0; y < 150; ++y)
    for (int x = 0; x < 48; ++x) ring.at(x, y, 3) = ((x - 22) * (x - 22) + (y - 70) * (y - 70) / 4) <= 300;
  for (int lanes : {2, 8}) {
    if (lanes > sn::io::ssim_widest_lanes()) continue;
    for (const Image* mask : {(const Image*)nullptr, (const Image*)&ring}) {
      const Image a = pair(0, 48, 150).first;
      const sn::io::SsimReference reference = sn::io::ssim_reference(a, 2, mask, 3, lanes);
      for (int kind = 0; kind < 3; ++kind) {
        const Image b = pair(kind, 48, 150).second;
        const double got = sn::io::ssim(reference, b);
        EXPECT_EQ(got, sn::io::ssim_lanes(lanes, a, b, 2, mask, 3)) << lanes << " lanes, kind " << kind;
        if (mask) {  // the oracle averages 3 channels
          int count = 0;
          EXPECT_NEAR(sn::io::ssim(sn::io::ssim_reference(a, -1, mask, 3, lanes), b), direct_ssim(a, b, *mask, &count), 1e-12);
        }
      }
    }
  }
  const sn::io::SsimReference reference = sn::io::ssim_reference(pair(0).first);
  EXPECT_THROW(sn::io::ssim(reference, Image(40, 29, 3)), std::invalid_argument);
  Image bad = pair(1).second;
  bad.at(3, 4, 1) = NAN;
  try {
    sn::io::ssim(reference, bad);
    ADD_FAILURE() << "a NaN was compared";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "ssim: pixel (4, 5) channel 2 is not a finite number");
  }
}

TEST(Ssim, RefusesWhatItCannotMeasure) {
  auto [a, b] = pair(0);
  Image small(10, 28, 3);
  EXPECT_THROW(sn::io::ssim(small, small), std::invalid_argument);  // narrower than the window
  EXPECT_THROW(sn::io::ssim(a, small), std::invalid_argument);
  Image none(40, 28, 4, 0.f);
  EXPECT_THROW(sn::io::ssim(a, b, -1, &none, 3), std::invalid_argument);
  // A channel not compared may hold anything; a compared one is named with the pixel.
  b.at(7, 2, 2) = INFINITY;
  EXPECT_NO_THROW(sn::io::ssim(a, b, 2));
  a.at(3, 4, 1) = std::nanf("");
  try {
    sn::io::ssim(a, b, 2);
    ADD_FAILURE() << "a NaN was compared";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("pixel (4, 5) channel 2 is not a finite number"), std::string::npos) << e.what();
  }
  a.at(3, 4, 1) = 0.5f;
  EXPECT_THROW(sn::io::ssim(a, b), std::invalid_argument);  // the infinity in channel 3
}

}  // namespace

#include "io/ssim.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/parallel.h"

#define SN_SSIM_INLINE inline __attribute__((always_inline))

namespace sn::io {

namespace {

constexpr double kSigma = 1.5, kC1 = 0.01 * 0.01, kC2 = 0.03 * 0.03;
constexpr int kR = kSsimRadius, kTaps = 2 * kSsimRadius + 1;
constexpr int kBandRows = 32;  // averaged rows per unit of work (about: the box splits evenly)

// Only the pixels [x0, x1] x [y0, y1] (interior ones: a mask's bounding box) are averaged; their
// windows never leave the image, so the averaged pixels need no edge rule ("reflect" in
// scikit-image).
struct Box {
  int x0, y0, x1, y1;
};

// One channel of the box, laid out for the filter: a and b over the box's rows widened by the
// radius (`rows` of `span` doubles, `span` = width + 2 radius), the mask over the box (1 where
// averaged, 0 elsewhere and in the padding to a whole vector), and room for the five filtered
// planes (x, y, x^2, y^2, xy) of the horizontal pass.
struct Planes {
  int width, height, rows, span;  // width: the box's, padded to a multiple of 8
  const double *a, *b, *mask;
  double* h;  // 5 planes of rows x width
};

// The channel's SSIM summed over its averaged pixels, in vectors V of doubles. Each plane's
// taps are summed in the window's order, as a direct sum would.
template <class V>
SN_SSIM_INLINE double channel_sum(const Planes& P, const double* k) {
  constexpr int L = int(sizeof(V) / sizeof(double));
  typedef V U __attribute__((aligned(8)));  // a vector at any double
  const size_t plane = size_t(P.rows) * P.width;
  for (int j = 0; j < P.rows; ++j)
    for (int x = 0; x < P.width; x += L) {
      V sx{}, sy{}, sxx{}, syy{}, sxy{};
      for (int d = 0; d < kTaps; ++d) {
        const V va = *(const U*)(P.a + size_t(j) * P.span + x + d), vb = *(const U*)(P.b + size_t(j) * P.span + x + d);
        const V ka = k[d] * va, kb = k[d] * vb;
        sx += ka, sy += kb, sxx += ka * va, syy += kb * vb, sxy += ka * vb;
      }
      double* o = P.h + size_t(j) * P.width + x;
      *(U*)o = sx, *(U*)(o + plane) = sy, *(U*)(o + 2 * plane) = sxx, *(U*)(o + 3 * plane) = syy;
      *(U*)(o + 4 * plane) = sxy;
    }
  V sum{};
  for (int y = 0; y < P.height; ++y)
    for (int x = 0; x < P.width; x += L) {
      V mx{}, my{}, xx{}, yy{}, xy{};
      for (int d = 0; d < kTaps; ++d) {
        const double* q = P.h + size_t(y + d) * P.width + x;
        mx += k[d] * *(const U*)q, my += k[d] * *(const U*)(q + plane), xx += k[d] * *(const U*)(q + 2 * plane);
        yy += k[d] * *(const U*)(q + 3 * plane), xy += k[d] * *(const U*)(q + 4 * plane);
      }
      const V vx = xx - mx * mx, vy = yy - my * my, cxy = xy - mx * my;
      const V s = (2 * mx * my + kC1) * (2 * cxy + kC2) / ((mx * mx + my * my + kC1) * (vx + vy + kC2));
      sum += *(const U*)(P.mask + size_t(y) * P.width + x) * s;
    }
  double total = 0;
  for (int i = 0; i < L; ++i) total += sum[i];
  return total;
}

using d2 = double __attribute__((vector_size(16)));
using d8 = double __attribute__((vector_size(64)));
double channel_sum_sse2(const Planes& P, const double* k) { return channel_sum<d2>(P, k); }
__attribute__((target("avx512f,avx2,fma"))) double channel_sum_avx512(const Planes& P, const double* k) {
  return channel_sum<d8>(P, k);
}

}  // namespace

int ssim_widest_lanes() {
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") ? 8 : 2;
}

double ssim(const Image& a, const Image& b, int channels, const Image* mask, int mask_channel) {
  static const int lanes = ssim_widest_lanes();
  return ssim_lanes(lanes, a, b, channels, mask, mask_channel);
}

double ssim_lanes(int lanes, const Image& a, const Image& b, int channels, const Image* mask, int mask_channel) {
  if (lanes != 2 && (lanes != 8 || ssim_widest_lanes() < 8))
    throw std::invalid_argument("ssim: no " + std::to_string(lanes) + "-lane filter on this CPU");
  if (a.width != b.width || a.height != b.height || a.channels != b.channels)
    throw std::invalid_argument("ssim: images differ in size: " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                                "x" + std::to_string(a.channels) + " vs " + std::to_string(b.width) + "x" +
                                std::to_string(b.height) + "x" + std::to_string(b.channels));
  const int w = a.width, h = a.height;
  if (w < kTaps || h < kTaps)
    throw std::invalid_argument("ssim: images of " + std::to_string(w) + "x" + std::to_string(h) +
                                " are smaller than the " + std::to_string(kTaps) + "x" + std::to_string(kTaps) + " window");
  if (channels < 0 || channels > a.channels) channels = a.channels;
  if (mask && (mask->width != w || mask->height != h || mask_channel < 0 || mask_channel >= mask->channels))
    throw std::invalid_argument("ssim: the mask does not match the images (size, or channel " +
                                std::to_string(mask_channel + 1) + " of " + std::to_string(mask->channels) + ")");
  double k[kTaps], ksum = 0;
  for (int d = -kR; d <= kR; ++d) ksum += k[d + kR] = std::exp(-0.5 * d * d / (kSigma * kSigma));
  for (double& v : k) v /= ksum;

  // The interior pixels that are averaged, and their bounding box (all of the interior
  // without a mask): a mesh covering part of the frame filters only around itself.
  Box box{w, h, -1, -1};
  size_t count = 0;
  for (int py = kR; py < h - kR; ++py)
    for (int px = kR; px < w - kR; ++px)
      if (!mask || mask->at(px, py, mask_channel) > 0.5f) {
        box = {std::min(box.x0, px), std::min(box.y0, py), std::max(box.x1, px), std::max(box.y1, py)};
        ++count;
      }
  if (box.x1 < 0) throw std::invalid_argument("ssim: the mask leaves no pixel at least 5 pixels inside the border");
  // Non-finite pixels are errors. A pass over every float in integer bit tests (which vectorize)
  // first; only when it finds one does the scan by channel name it (or find it in a channel
  // not compared).
  const auto any_nonfinite = [](const std::vector<float>& v) {
    uint32_t bad = 0;
    for (const float f : v) {
      uint32_t u;
      std::memcpy(&u, &f, sizeof u);
      bad |= uint32_t((u & 0x7f800000u) == 0x7f800000u);
    }
    return bad != 0;
  };
  if (any_nonfinite(a.pixels) || any_nonfinite(b.pixels))
    for (int c = 0; c < channels; ++c)
      for (int i = 0; i < w * h; ++i)
        if (!std::isfinite(a.pixels[size_t(i) * a.channels + c]) || !std::isfinite(b.pixels[size_t(i) * b.channels + c]))
          throw std::invalid_argument("ssim: pixel (" + std::to_string(i % w + 1) + ", " + std::to_string(i / w + 1) +
                                    ") channel " + std::to_string(c + 1) + " is not a finite number");

  // The box in bands of rows, each filtered on its own (its horizontal pass also covers the
  // radius above and below it): the (channel, band) units run on the threads, and their sums
  // add in a fixed order, so the value does not depend on how many threads ran.
  const int width = (box.x1 - box.x0 + 1 + 7) / 8 * 8, height = box.y1 - box.y0 + 1;
  const int bands = std::max(1, (height + kBandRows / 2) / kBandRows);
  const int band_rows = (height + bands - 1) / bands;
  // The averaged pixels as 1 (0 elsewhere and in the padding), once for every channel and band.
  // (The threads read it through `plane`: in the lambda, `averaged` would be each thread's own.)
  thread_local std::vector<double> averaged;
  averaged.assign(size_t(width) * size_t(height), 0.0);
  double* const plane = averaged.data();
  for (int y = box.y0; y <= box.y1; ++y)
    for (int x = box.x0; x <= box.x1; ++x)
      plane[size_t(y - box.y0) * size_t(width) + size_t(x - box.x0)] = !mask || mask->at(x, y, mask_channel) > 0.5f;
  std::vector<double> sums(size_t(channels) * size_t(bands));
  parallel_for(channels * bands, default_threads(), [&](int u) {
    const int c = u / bands, y0 = box.y0 + (u % bands) * band_rows;
    Planes P;
    P.width = width;
    P.height = std::min(band_rows, box.y1 + 1 - y0);
    P.rows = P.height + 2 * kR;
    P.span = P.width + 2 * kR;
    // One buffer per thread, reused: a table scores thousands of images, and fresh pages for
    // each would cost more than the filter. Every float of it is written before it is read.
    const size_t in = size_t(P.rows) * P.span;
    thread_local std::vector<double> buffer;
    buffer.resize(2 * in + 5 * size_t(P.rows) * P.width);
    double *pa = buffer.data(), *pb = pa + in;
    P.a = pa, P.b = pb, P.h = pb + in;
    P.mask = plane + size_t(y0 - box.y0) * size_t(width);
    // Columns beyond the image (the padding) are 0; their pixels are not averaged.
    const int x0 = box.x0 - kR, inside = std::min(P.span, w - x0);
    for (int j = 0; j < P.rows; ++j) {
      const size_t row = size_t(y0 - kR + j) * w + x0;
      const float *ra = a.pixels.data() + row * a.channels + c, *rb = b.pixels.data() + row * b.channels + c;
      double *oa = pa + size_t(j) * P.span, *ob = pb + size_t(j) * P.span;
      for (int i = 0; i < inside; ++i) oa[i] = ra[size_t(i) * a.channels], ob[i] = rb[size_t(i) * b.channels];
      std::fill(oa + inside, oa + P.span, 0.0), std::fill(ob + inside, ob + P.span, 0.0);
    }
    sums[size_t(u)] = lanes == 8 ? channel_sum_avx512(P, k) : channel_sum_sse2(P, k);
  });
  double total = 0;
  for (int c = 0; c < channels; ++c) {
    double sum = 0;
    for (int band = 0; band < bands; ++band) sum += sums[size_t(c) * size_t(bands) + size_t(band)];
    total += sum / double(count);
  }
  return total / channels;
}

}  // namespace sn::io

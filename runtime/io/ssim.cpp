#include "io/ssim.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
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

// One channel of one band of the box's rows, the unit of work: the reference image's rows of the
// band widened by the radius (`rows` x span doubles, 0 beyond the image), and its local means
// `mx` and second moments `xx` at the band's pixels (height x width).
struct Unit {
  int c, y0, height, rows;
  std::vector<double> a, mx, xx;
};

}  // namespace

struct SsimReference::Data {
  int lanes, w, h, image_channels, channels;
  Box box;
  std::size_t count;  // averaged pixels per channel
  int width, span;    // width: the box's, padded to a multiple of 8; span: width + 2 radius
  double k[kTaps];
  std::vector<double> averaged;  // width x box height: 1 where averaged, 0 elsewhere and in the padding
  std::vector<Unit> units;       // channel by channel, each band by band
};

namespace {

using Data = SsimReference::Data;

// The reference's planes of a unit: the horizontal pass over its rows (x, x^2 in `h`, 2 planes of
// rows x width), then the vertical one (mx, xx). Here and below the window's taps are summed in
// its order, as a direct sum would, in vectors V of doubles (U: one that may start at any double).
template <class V>
SN_SSIM_INLINE void reference_planes(Unit& u, const Data& D, double* h) {
  constexpr int L = int(sizeof(V) / sizeof(double));
  typedef V U __attribute__((aligned(8)));
  const std::size_t plane = std::size_t(u.rows) * D.width;
  for (int j = 0; j < u.rows; ++j)
    for (int x = 0; x < D.width; x += L) {
      V sx{}, sxx{};
      for (int d = 0; d < kTaps; ++d) {
        const V va = *(const U*)(u.a.data() + std::size_t(j) * D.span + x + d), ka = D.k[d] * va;
        sx += ka, sxx += ka * va;
      }
      *(U*)(h + std::size_t(j) * D.width + x) = sx, *(U*)(h + plane + std::size_t(j) * D.width + x) = sxx;
    }
  for (int y = 0; y < u.height; ++y)
    for (int x = 0; x < D.width; x += L) {
      V mx{}, xx{};
      for (int d = 0; d < kTaps; ++d) {
        const double* q = h + std::size_t(y + d) * D.width + x;
        mx += D.k[d] * *(const U*)q, xx += D.k[d] * *(const U*)(q + plane);
      }
      *(U*)(u.mx.data() + std::size_t(y) * D.width + x) = mx, *(U*)(u.xx.data() + std::size_t(y) * D.width + x) = xx;
    }
}

// The unit's SSIM summed over its averaged pixels, against `b`'s rows of the unit (as u.a):
// the horizontal pass (y, y^2, xy in `h`, 3 planes), the vertical one, the formula.
template <class V>
SN_SSIM_INLINE double unit_sum(const Unit& u, const Data& D, const double* b, double* h) {
  constexpr int L = int(sizeof(V) / sizeof(double));
  typedef V U __attribute__((aligned(8)));
  const std::size_t plane = std::size_t(u.rows) * D.width;
  for (int j = 0; j < u.rows; ++j)
    for (int x = 0; x < D.width; x += L) {
      V sy{}, syy{}, sxy{};
      for (int d = 0; d < kTaps; ++d) {
        const std::size_t at = std::size_t(j) * D.span + x + d;
        const V va = *(const U*)(u.a.data() + at), vb = *(const U*)(b + at);
        const V ka = D.k[d] * va, kb = D.k[d] * vb;
        sy += kb, syy += kb * vb, sxy += ka * vb;
      }
      double* o = h + std::size_t(j) * D.width + x;
      *(U*)o = sy, *(U*)(o + plane) = syy, *(U*)(o + 2 * plane) = sxy;
    }
  const double* mask = D.averaged.data() + std::size_t(u.y0 - D.box.y0) * D.width;
  V sum{};
  for (int y = 0; y < u.height; ++y)
    for (int x = 0; x < D.width; x += L) {
      V my{}, yy{}, xy{};
      for (int d = 0; d < kTaps; ++d) {
        const double* q = h + std::size_t(y + d) * D.width + x;
        my += D.k[d] * *(const U*)q, yy += D.k[d] * *(const U*)(q + plane), xy += D.k[d] * *(const U*)(q + 2 * plane);
      }
      const std::size_t at = std::size_t(y) * D.width + x;
      const V mx = *(const U*)(u.mx.data() + at), xx = *(const U*)(u.xx.data() + at);
      const V vx = xx - mx * mx, vy = yy - my * my, cxy = xy - mx * my;
      const V s = (2 * mx * my + kC1) * (2 * cxy + kC2) / ((mx * mx + my * my + kC1) * (vx + vy + kC2));
      sum += *(const U*)(mask + at) * s;
    }
  double total = 0;
  for (int i = 0; i < L; ++i) total += sum[i];
  return total;
}

using d2 = double __attribute__((vector_size(16)));
using d8 = double __attribute__((vector_size(64)));
void reference_planes_sse2(Unit& u, const Data& D, double* h) { reference_planes<d2>(u, D, h); }
__attribute__((target("avx512f,avx2,fma"))) void reference_planes_avx512(Unit& u, const Data& D, double* h) {
  reference_planes<d8>(u, D, h);
}
double unit_sum_sse2(const Unit& u, const Data& D, const double* b, double* h) { return unit_sum<d2>(u, D, b, h); }
__attribute__((target("avx512f,avx2,fma"))) double unit_sum_avx512(const Unit& u, const Data& D, const double* b,
                                                                   double* h) {
  return unit_sum<d8>(u, D, b, h);
}

void check_same_size(int w, int h, int channels, const Image& b) {
  if (b.width != w || b.height != h || b.channels != channels)
    throw std::invalid_argument("ssim: images differ in size: " + std::to_string(w) + "x" + std::to_string(h) + "x" +
                                std::to_string(channels) + " vs " + std::to_string(b.width) + "x" +
                                std::to_string(b.height) + "x" + std::to_string(b.channels));
}

// `img`'s channel c over the unit's rows, widened by the radius, as doubles (0 beyond the image).
void copy_rows(const Image& img, const Unit& u, const Data& D, double* out) {
  const int x0 = D.box.x0 - kR, inside = std::min(D.span, D.w - x0);
  for (int j = 0; j < u.rows; ++j) {
    const float* r = img.pixels.data() + (std::size_t(u.y0 - kR + j) * D.w + x0) * img.channels + u.c;
    double* o = out + std::size_t(j) * D.span;
    for (int i = 0; i < inside; ++i) o[i] = r[std::size_t(i) * img.channels];
    std::fill(o + inside, o + D.span, 0.0);
  }
}

// One buffer per thread, reused: a table scores thousands of images, and fresh pages for each
// would cost more than the filter. Every double of it is written before it is read.
double* scratch(std::size_t n) {
  thread_local std::vector<double> buffer;
  if (buffer.size() < n) buffer.resize(n);
  return buffer.data();
}

}  // namespace

int ssim_widest_lanes() {
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") ? 8 : 2;
}

SsimReference ssim_reference(const Image& a, int channels, const Image* mask, int mask_channel, int lanes) {
  static const int widest = ssim_widest_lanes();
  if (lanes == 0) lanes = widest;
  if (lanes != 2 && (lanes != 8 || widest < 8))
    throw std::invalid_argument("ssim: no " + std::to_string(lanes) + "-lane filter on this CPU");
  auto D = std::make_shared<Data>();
  const int w = a.width, h = a.height;
  if (w < kTaps || h < kTaps)
    throw std::invalid_argument("ssim: images of " + std::to_string(w) + "x" + std::to_string(h) +
                                " are smaller than the " + std::to_string(kTaps) + "x" + std::to_string(kTaps) + " window");
  if (channels < 0 || channels > a.channels) channels = a.channels;
  if (mask && (mask->width != w || mask->height != h || mask_channel < 0 || mask_channel >= mask->channels))
    throw std::invalid_argument("ssim: the mask does not match the images (size, or channel " +
                                std::to_string(mask_channel + 1) + " of " + std::to_string(mask->channels) + ")");
  D->lanes = lanes, D->w = w, D->h = h, D->image_channels = a.channels, D->channels = channels;
  double ksum = 0;
  for (int d = -kR; d <= kR; ++d) ksum += D->k[d + kR] = std::exp(-0.5 * d * d / (kSigma * kSigma));
  for (double& v : D->k) v /= ksum;

  // The interior pixels that are averaged, and their bounding box (all of the interior
  // without a mask): a mesh covering part of the frame filters only around itself.
  Box box{w, h, -1, -1};
  std::size_t count = 0;
  for (int py = kR; py < h - kR; ++py)
    for (int px = kR; px < w - kR; ++px)
      if (!mask || mask->at(px, py, mask_channel) > 0.5f) {
        box = {std::min(box.x0, px), std::min(box.y0, py), std::max(box.x1, px), std::max(box.y1, py)};
        ++count;
      }
  if (box.x1 < 0) throw std::invalid_argument("ssim: the mask leaves no pixel at least 5 pixels inside the border");
  check_finite(a, channels, "ssim");
  D->box = box, D->count = count;

  // The box in bands of rows, each filtered on its own (its horizontal pass also covers the
  // radius above and below it): the (channel, band) units run on the threads, and their sums
  // add in a fixed order, so the value does not depend on how many threads ran.
  const int width = (box.x1 - box.x0 + 1 + 7) / 8 * 8, height = box.y1 - box.y0 + 1;
  const int bands = std::max(1, (height + kBandRows / 2) / kBandRows);
  const int band_rows = (height + bands - 1) / bands;
  D->width = width, D->span = width + 2 * kR;
  D->averaged.assign(std::size_t(width) * std::size_t(height), 0.0);
  for (int y = box.y0; y <= box.y1; ++y)
    for (int x = box.x0; x <= box.x1; ++x)
      D->averaged[std::size_t(y - box.y0) * std::size_t(width) + std::size_t(x - box.x0)] =
          !mask || mask->at(x, y, mask_channel) > 0.5f;
  for (int c = 0; c < channels; ++c)
    for (int band = 0; band < bands; ++band) {
      Unit u;
      u.c = c, u.y0 = box.y0 + band * band_rows;
      u.height = std::min(band_rows, box.y1 + 1 - u.y0), u.rows = u.height + 2 * kR;
      D->units.push_back(std::move(u));
    }
  parallel_for(int(D->units.size()), default_threads(), [&](int i) {
    Unit& u = D->units[std::size_t(i)];
    u.a.resize(std::size_t(u.rows) * D->span);
    u.mx.resize(std::size_t(u.height) * width), u.xx.resize(std::size_t(u.height) * width);
    copy_rows(a, u, *D, u.a.data());
    double* h = scratch(2 * std::size_t(u.rows) * width);
    lanes == 8 ? reference_planes_avx512(u, *D, h) : reference_planes_sse2(u, *D, h);
  });
  return SsimReference(std::move(D));
}

double ssim(const SsimReference& reference, const Image& b) {
  const Data& D = reference.data();
  check_same_size(D.w, D.h, D.image_channels, b);
  check_finite(b, D.channels, "ssim");
  std::vector<double> sums(D.units.size());
  parallel_for(int(D.units.size()), default_threads(), [&](int i) {
    const Unit& u = D.units[std::size_t(i)];
    const std::size_t in = std::size_t(u.rows) * D.span;
    double* rows = scratch(in + 3 * std::size_t(u.rows) * D.width);
    copy_rows(b, u, D, rows);
    sums[std::size_t(i)] = D.lanes == 8 ? unit_sum_avx512(u, D, rows, rows + in) : unit_sum_sse2(u, D, rows, rows + in);
  });
  const std::size_t bands = D.units.size() / std::size_t(D.channels);
  double total = 0;
  for (std::size_t c = 0; c < std::size_t(D.channels); ++c) {
    double sum = 0;
    for (std::size_t band = 0; band < bands; ++band) sum += sums[c * bands + band];
    total += sum / double(D.count);
  }
  return total / D.channels;
}

double ssim(const Image& a, const Image& b, int channels, const Image* mask, int mask_channel) {
  return ssim_lanes(0, a, b, channels, mask, mask_channel);
}

double ssim_lanes(int lanes, const Image& a, const Image& b, int channels, const Image* mask, int mask_channel) {
  check_same_size(a.width, a.height, a.channels, b);
  return ssim(ssim_reference(a, channels, mask, mask_channel, lanes), b);
}

}  // namespace sn::io

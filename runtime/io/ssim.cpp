#include "io/ssim.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace sn::io {

namespace {

constexpr double kSigma = 1.5, kC1 = 0.01 * 0.01, kC2 = 0.03 * 0.03;

// The window of a pixel at least kSsimRadius from the border never leaves the image, so the
// averaged pixels need no edge rule ("reflect" in scikit-image): only those are filtered.
// Horizontal pass over every row for the interior columns, then vertical for the interior rows;
// the five planes (x, y, x^2, y^2, xy) in one sweep.
struct Moments {
  double x, y, xx, yy, xy;
};

// Only the pixels [x0, x1] x [y0, y1] (interior ones: a mask's bounding box) are filtered.
struct Box {
  int x0, y0, x1, y1;
};
std::vector<Moments> blur_interior(const std::vector<double>& a, const std::vector<double>& b, int w, int h,
                                   const double* k, const Box& box) {
  const int r = kSsimRadius;
  std::vector<Moments> rows(size_t(w) * h), out(size_t(w) * h);
  for (int y = box.y0 - r; y <= box.y1 + r; ++y)
    for (int x = box.x0; x <= box.x1; ++x) {
      Moments m{0, 0, 0, 0, 0};
      for (int d = -r; d <= r; ++d) {
        const size_t i = size_t(y) * w + x + d;
        const double kv = k[d + r], va = a[i], vb = b[i];
        m.x += kv * va, m.y += kv * vb, m.xx += kv * va * va, m.yy += kv * vb * vb, m.xy += kv * va * vb;
      }
      rows[size_t(y) * w + x] = m;
    }
  for (int y = box.y0; y <= box.y1; ++y)
    for (int x = box.x0; x <= box.x1; ++x) {
      Moments m{0, 0, 0, 0, 0};
      for (int d = -r; d <= r; ++d) {
        const Moments& q = rows[size_t(y + d) * w + x];
        const double kv = k[d + r];
        m.x += kv * q.x, m.y += kv * q.y, m.xx += kv * q.xx, m.yy += kv * q.yy, m.xy += kv * q.xy;
      }
      out[size_t(y) * w + x] = m;
    }
  return out;
}

}  // namespace

double ssim(const Image& a, const Image& b, int channels, const Image* mask, int mask_channel) {
  if (a.width != b.width || a.height != b.height || a.channels != b.channels)
    throw std::invalid_argument("ssim: images differ in size: " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                                "x" + std::to_string(a.channels) + " vs " + std::to_string(b.width) + "x" +
                                std::to_string(b.height) + "x" + std::to_string(b.channels));
  const int w = a.width, h = a.height, win = 2 * kSsimRadius + 1;
  if (w < win || h < win)
    throw std::invalid_argument("ssim: images of " + std::to_string(w) + "x" + std::to_string(h) +
                                " are smaller than the " + std::to_string(win) + "x" + std::to_string(win) + " window");
  if (channels < 0 || channels > a.channels) channels = a.channels;
  if (mask && (mask->width != w || mask->height != h || mask_channel < 0 || mask_channel >= mask->channels))
    throw std::invalid_argument("ssim: the mask does not match the images (size, or channel " +
                                std::to_string(mask_channel + 1) + " of " + std::to_string(mask->channels) + ")");
  double k[2 * kSsimRadius + 1], ksum = 0;
  for (int d = -kSsimRadius; d <= kSsimRadius; ++d) ksum += k[d + kSsimRadius] = std::exp(-0.5 * d * d / (kSigma * kSigma));
  for (double& v : k) v /= ksum;

  // The interior pixels that are averaged, and their bounding box (all of the interior
  // without a mask): a mesh covering part of the frame filters only around itself.
  const int r = kSsimRadius;
  Box box{w, h, -1, -1};
  for (int py = r; py < h - r; ++py)
    for (int px = r; px < w - r; ++px)
      if (!mask || mask->at(px, py, mask_channel) > 0.5f)
        box = {std::min(box.x0, px), std::min(box.y0, py), std::max(box.x1, px), std::max(box.y1, py)};
  if (box.x1 < 0) throw std::invalid_argument("ssim: the mask leaves no pixel at least 5 pixels inside the border");
  const size_t n = size_t(w) * h;
  double total = 0;
  for (int c = 0; c < channels; ++c) {
    std::vector<double> x(n), y(n);
    for (size_t i = 0; i < n; ++i) {
      x[i] = a.pixels[i * a.channels + c], y[i] = b.pixels[i * b.channels + c];
      if (!std::isfinite(x[i]) || !std::isfinite(y[i]))
        throw std::invalid_argument("ssim: pixel (" + std::to_string(i % w + 1) + ", " + std::to_string(i / w + 1) +
                                    ") channel " + std::to_string(c + 1) + " is not a finite number");
    }
    const auto m = blur_interior(x, y, w, h, k, box);
    double sum = 0;
    size_t count = 0;
    for (int py = box.y0; py <= box.y1; ++py)
      for (int px = box.x0; px <= box.x1; ++px) {
        if (mask && mask->at(px, py, mask_channel) <= 0.5f) continue;
        const Moments& q = m[size_t(py) * w + px];
        const double vx = q.xx - q.x * q.x, vy = q.yy - q.y * q.y, cxy = q.xy - q.x * q.y;
        sum += (2 * q.x * q.y + kC1) * (2 * cxy + kC2) / ((q.x * q.x + q.y * q.y + kC1) * (vx + vy + kC2));
        ++count;
      }
    total += sum / double(count);
  }
  return total / channels;
}

}  // namespace sn::io

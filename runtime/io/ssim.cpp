#include "io/ssim.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace sn::io {

namespace {

constexpr double kSigma = 1.5, kC1 = 0.01 * 0.01, kC2 = 0.03 * 0.03;

// scipy.ndimage "reflect": d c b a | a b c d | d c b a.
int reflect(int i, int n) {
  while (i < 0 || i >= n) i = i < 0 ? -i - 1 : 2 * n - i - 1;
  return i;
}

// Separable Gaussian filter of a w x h plane.
std::vector<double> blur(const std::vector<double>& in, int w, int h, const double* k) {
  std::vector<double> tmp(in.size()), out(in.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double s = 0;
      for (int d = -kSsimRadius; d <= kSsimRadius; ++d) s += k[d + kSsimRadius] * in[size_t(y) * w + reflect(x + d, w)];
      tmp[size_t(y) * w + x] = s;
    }
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double s = 0;
      for (int d = -kSsimRadius; d <= kSsimRadius; ++d) s += k[d + kSsimRadius] * tmp[size_t(reflect(y + d, h)) * w + x];
      out[size_t(y) * w + x] = s;
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

  const size_t n = size_t(w) * h;
  double total = 0;
  for (int c = 0; c < channels; ++c) {
    std::vector<double> x(n), y(n), xx(n), yy(n), xy(n);
    for (size_t i = 0; i < n; ++i) {
      x[i] = a.pixels[i * a.channels + c], y[i] = b.pixels[i * b.channels + c];
      if (!std::isfinite(x[i]) || !std::isfinite(y[i]))
        throw std::invalid_argument("ssim: pixel (" + std::to_string(i % w + 1) + ", " + std::to_string(i / w + 1) +
                                    ") channel " + std::to_string(c + 1) + " is not a finite number");
      xx[i] = x[i] * x[i], yy[i] = y[i] * y[i], xy[i] = x[i] * y[i];
    }
    auto mx = blur(x, w, h, k), my = blur(y, w, h, k), mxx = blur(xx, w, h, k), myy = blur(yy, w, h, k),
         mxy = blur(xy, w, h, k);
    double sum = 0;
    size_t count = 0;
    for (int py = kSsimRadius; py < h - kSsimRadius; ++py)
      for (int px = kSsimRadius; px < w - kSsimRadius; ++px) {
        if (mask && mask->at(px, py, mask_channel) <= 0.5f) continue;
        const size_t i = size_t(py) * w + px;
        const double vx = mxx[i] - mx[i] * mx[i], vy = myy[i] - my[i] * my[i], cxy = mxy[i] - mx[i] * my[i];
        sum += (2 * mx[i] * my[i] + kC1) * (2 * cxy + kC2) / ((mx[i] * mx[i] + my[i] * my[i] + kC1) * (vx + vy + kC2));
        ++count;
      }
    if (count == 0) throw std::invalid_argument("ssim: the mask leaves no pixel at least 5 pixels inside the border");
    total += sum / double(count);
  }
  return total / channels;
}

}  // namespace sn::io

// The structural similarity index (SSIM) of Wang, Bovik, Sheikh and Simoncelli (IEEE TIP 2004),
// computed as their paper and scikit-image's structural_similarity(gaussian_weights=True,
// sigma=1.5, use_sample_covariance=False, data_range=1) do: local means, variances and the
// covariance under an 11x11 Gaussian window (sigma 1.5, cut at 3.5 sigma, normalised; no edge
// rule is needed: only pixels whose window lies inside the image are averaged), C1 = (0.01 L)^2,
// C2 = (0.03 L)^2 with L = 1, and
//   SSIM(x, y) = (2 mx my + C1)(2 sxy + C2) / ((mx^2 + my^2 + C1)(sx^2 + sy^2 + C2))
// averaged over pixels at least 5 pixels from the border, then over channels. 1 means equal.
#pragma once
#include <memory>

#include "io/image.h"

namespace sn::io {

constexpr int kSsimRadius = 5;  // the window is 2 * 5 + 1 pixels wide

// Channels [0, channels) (all when -1). With `mask`, only pixels whose mask channel is > 0.5
// are averaged (the window still sees their neighbours). Throws when the images differ in size,
// are narrower or lower than the window, or no pixel is left to average.
double ssim(const Image& a, const Image& b, int channels = -1, const Image* mask = nullptr, int mask_channel = 3);

// The first image's part of ssim, prepared once to compare many images with it (a table scores
// each truth view against hundreds of networks' renders): the box of averaged pixels and, per
// channel, the image's local means and second moments. ssim(ssim_reference(a, ...), b) is
// ssim(a, b, ...) to the bit; a comparison then filters three planes, not five.
class SsimReference {
 public:
  struct Data;
  explicit SsimReference(std::shared_ptr<const Data> d) : d_(std::move(d)) {}
  const Data& data() const { return *d_; }

 private:
  std::shared_ptr<const Data> d_;  // shared by copies; never changed after it is made
};
// Throws as ssim does for `a` and the mask. `lanes` as for ssim_lanes; 0: the widest.
SsimReference ssim_reference(const Image& a, int channels = -1, const Image* mask = nullptr, int mask_channel = 3,
                             int lanes = 0);
// Throws when `b` differs from the reference's image in size or holds a non-finite value in a
// compared channel.
double ssim(const SsimReference& reference, const Image& b);

// ssim with the filter in vectors of `lanes` doubles: 2 (SSE2, every x86-64 CPU) or 8 (AVX-512,
// where the CPU has it), or 0 for the widest, which ssim uses. For tests of each path.
int ssim_widest_lanes();
double ssim_lanes(int lanes, const Image& a, const Image& b, int channels = -1, const Image* mask = nullptr,
                  int mask_channel = 3);

}  // namespace sn::io

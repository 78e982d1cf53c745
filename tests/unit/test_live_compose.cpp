// The live view's error heatmap and side-by-side panel: the compute pass against its
// double-precision twin, on images with uncovered pixels, NaN and Inf.
#include <gtest/gtest.h>

#include <epoxy/gl.h>

#include <cmath>
#include <limits>
#include <random>

#include "gl/context.h"
#include "gl/render_target.h"
#include "gl/compose.h"

using namespace sn;

namespace {

// A target whose attachment 0 holds `img` (rows top first, as RenderTarget::read returns them).
std::unique_ptr<gl::RenderTarget> target_from(const io::Image& img) {
  auto t = std::make_unique<gl::RenderTarget>(img.width, img.height);
  std::vector<float> flipped(img.pixels.size());
  size_t row = size_t(img.width) * 4;
  for (int y = 0; y < img.height; ++y)
    std::copy_n(img.pixels.begin() + size_t(img.height - 1 - y) * row, row, flipped.begin() + size_t(y) * row);
  glTextureSubImage2D(t->color_texture(0), 0, 0, 0, img.width, img.height, GL_RGBA, GL_FLOAT, flipped.data());
  return t;
}

io::Image random_image(int w, int h, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-0.2f, 1.2f);
  io::Image img(w, h, 4);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      for (int c = 0; c < 3; ++c) img.at(x, y, c) = u(rng);
      img.at(x, y, 3) = (x * 7 + y * 3) % 5 == 0 ? 0.f : 1.f;  // some pixels uncovered
    }
  return img;
}

void expect_images_near(const io::Image& gpu, const io::Image& cpu, double tol) {
  ASSERT_EQ(gpu.width, cpu.width);
  ASSERT_EQ(gpu.height, cpu.height);
  for (int y = 0; y < gpu.height; ++y)
    for (int x = 0; x < gpu.width; ++x)
      for (int c = 0; c < 4; ++c) {
        float g = gpu.at(x, y, c), r = cpu.at(x, y, c);
        if (std::isnan(g) && std::isnan(r)) continue;  // a NaN copied into a side panel
        if (std::isinf(g) || std::isinf(r)) {
          ASSERT_EQ(g, r) << "pixel (" << x << "," << y << ") channel " << c;
          continue;
        }
        ASSERT_NEAR(g, r, tol) << "pixel (" << x << "," << y << ") channel " << c;
      }
}

}  // namespace

TEST(LiveCompose, HeatTwinEndPoints) {
  using io::Colormap;
  std::array<double, 4> truth{0.5, 0.5, 0.5, 1};
  auto at0 = io::error_heat(truth, truth, 0.25);
  auto top = io::error_heat({0.75, 0.75, 0.75, 1}, truth, 0.25);  // mean |error| = scale
  auto over = io::error_heat({1.5, 1.5, 1.5, 1}, truth, 0.25);    // saturates
  io::Color c0 = io::colormap(Colormap::inferno, 0), c1 = io::colormap(Colormap::inferno, 1);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(at0[k], c0[k], 1e-7);
    EXPECT_NEAR(top[k], c1[k], 1e-7);
    EXPECT_NEAR(over[k], c1[k], 1e-7);
  }
  EXPECT_EQ(at0[3], 1);
  // Half the scale sits halfway up the colormap; the error is the mean over R, G, B.
  auto half = io::error_heat({0.5 + 3 * 0.125, 0.5, 0.5, 1}, truth, 0.25, Colormap::gray);
  EXPECT_NEAR(half[0], 0.5, 1e-7);
  // Uncovered: transparent black. Non-finite: magenta, whatever the scale.
  auto none = io::error_heat({0.9, 0.1, 0.3, 0}, {0.1, 0.2, 0.3, 0}, 0.25);
  EXPECT_EQ(none, (std::array<double, 4>{0, 0, 0, 0}));
  double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(io::error_heat({nan, 0, 0, 1}, truth, 0.25), (std::array<double, 4>{1, 0, 1, 1}));
}

TEST(LiveCompose, GpuMatchesTwin) {
  gl::current();
  const int w = 37, h = 23;  // not a multiple of the 8x8 workgroup
  io::Image n = random_image(w, h, 1), t = random_image(w, h, 2);
  const float inf = std::numeric_limits<float>::infinity();
  n.at(3, 4, 0) = std::numeric_limits<float>::quiet_NaN(), n.at(3, 4, 3) = 1;
  n.at(10, 11, 2) = -inf, n.at(10, 11, 3) = 1;
  auto nt = target_from(n), tt = target_from(t);
  io::Image n_seen = nt->read(), t_seen = tt->read();  // what the GPU reads, NaN included
  ASSERT_TRUE(std::isnan(n_seen.at(3, 4, 0)));
  for (auto map : {io::Colormap::inferno, io::Colormap::viridis, io::Colormap::gray})
    for (auto layout : {io::Layout::error, io::Layout::side}) {
      auto [ow, oh] = io::composed_size(layout, w, h);
      gl::RenderTarget out(ow, oh);
      gl::compose(layout, *nt, *tt, 0.3, map, out);
      io::Image gpu = out.read(), cpu = io::compose(layout, n_seen, t_seen, 0.3, map);
      expect_images_near(gpu, cpu, 2e-6);
    }
  // The NaN pixel is magenta in the heatmap, and some covered pixels are neither black nor magenta.
  gl::RenderTarget out(w, h);
  gl::compose(io::Layout::error, *nt, *tt, 0.3, io::Colormap::inferno, out);
  io::Image e = out.read();
  EXPECT_EQ(e.at(3, 4, 0), 1.f);
  EXPECT_EQ(e.at(3, 4, 1), 0.f);
  EXPECT_EQ(e.at(3, 4, 2), 1.f);
  EXPECT_EQ(e.at(10, 11, 1), 0.f);
  EXPECT_EQ(e.at(0, 0, 3), 0.f);  // (0,0) is uncovered in both
}

TEST(LiveCompose, SizeAndScaleErrors) {
  gl::current();
  gl::RenderTarget a(8, 8), b(9, 8), out(8, 8), side(16, 16);
  try {
    gl::compose(io::Layout::error, a, b, 0.25, io::Colormap::inferno, out);
    FAIL() << "mismatched sizes were accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("8x8 but the truth image is 9x8"), std::string::npos) << e.what();
  }
  EXPECT_THROW(gl::compose(io::Layout::error, a, a, 0, io::Colormap::inferno, out), std::invalid_argument);
  EXPECT_THROW(gl::compose(io::Layout::error, a, a, NAN, io::Colormap::inferno, out), std::invalid_argument);
  EXPECT_THROW(gl::compose(io::Layout::side, a, a, 0.25, io::Colormap::inferno, out), std::invalid_argument);
  EXPECT_NO_THROW(gl::compose(io::Layout::side, a, a, 0.25, io::Colormap::inferno, side));
}

// Figures: text lands where asked and only there, grids place and composite panels exactly,
// heatmaps map values through the colormap and show NaN instead of hiding it.
#include <gtest/gtest.h>

#include <cmath>

#include "io/figure.h"

using namespace sn::io;

namespace {

bool same(const Color& a, const Image& img, int x, int y, float tol = 1e-5f) {
  for (int k = 0; k < 3; ++k)
    if (std::fabs(a[k] - img.at(x, y, k)) > tol) return false;
  return true;
}

}  // namespace

TEST(Figure, FontIsFound) { EXPECT_FALSE(label_font().empty()); }

TEST(Figure, TextStaysInsideItsBox) {
  Image img(200, 60, 3, 0.f);
  auto [w, h] = text_size("Label 0.0123", 16);
  ASSERT_GT(w, 40);
  ASSERT_GT(h, 10);
  draw_text(img, 20, 10, "Label 0.0123", {16, {1, 0, 0}, Align::left});
  int lit = 0, outside = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      float r = img.at(x, y, 0);
      EXPECT_EQ(img.at(x, y, 1), 0.f);  // red text: green and blue untouched
      if (r > 0.1f) {
        ++lit;
        if (x < 19 || x > 20 + w + 1 || y < 9 || y > 10 + h + 1) ++outside;
      }
    }
  EXPECT_GT(lit, 50);
  EXPECT_EQ(outside, 0);
}

TEST(Figure, UnicodePunctuationIsDrawnAsAscii) {
  // "Table 4.1 \u2014 8 \u00d7 12" is drawn as "Table 4.1 - 8 x 12": same pixels, no boxes.
  Image a(300, 30, 1, 0.f), b(300, 30, 1, 0.f);
  draw_text(a, 2, 2, "Table 4.1 \u2014 8 \u00d7 12", {16, {1, 1, 1}, Align::left});
  draw_text(b, 2, 2, "Table 4.1 - 8 x 12", {16, {1, 1, 1}, Align::left});
  EXPECT_EQ(a.pixels, b.pixels);
  EXPECT_EQ(text_size("\u00e6", 16), text_size("?", 16));  // unknown: a visible '?'
}

TEST(Figure, CentredTextIsCentred) {
  Image img(201, 40, 1, 0.f);
  draw_text(img, 100, 5, "MMMM", {20, {1, 1, 1}, Align::center});
  double sum = 0, sx = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) sum += img.at(x, y, 0), sx += x * img.at(x, y, 0);
  ASSERT_GT(sum, 0);
  EXPECT_NEAR(sx / sum, 100.0, 3.0);
}

TEST(Figure, GridPlacesAndCompositesPanels) {
  Image a(10, 8, 3, 0.25f), b(10, 8, 4, 0.f);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 10; ++x) {
      b.at(x, y, 0) = 1.f;                 // red where covered,
      b.at(x, y, 3) = x < 5 ? 1.f : 0.f;   // left half covered only
    }
  GridStyle s;
  s.padding = 4;
  s.background = {1, 1, 1};
  Image g = grid({{a, ""}, {b, ""}}, s);
  // No captions, no title: width = pad + 2 * (10 + pad), height = pad + 8 + pad.
  EXPECT_EQ(g.width, 4 + 2 * 14);
  EXPECT_EQ(g.height, 16);
  EXPECT_EQ(g.channels, 3);
  EXPECT_TRUE(same({0.25f, 0.25f, 0.25f}, g, 4, 4));
  EXPECT_TRUE(same({0.25f, 0.25f, 0.25f}, g, 13, 11));
  EXPECT_TRUE(same({1, 1, 1}, g, 2, 2));                // padding = background
  EXPECT_TRUE(same({1, 0, 0}, g, 18 + 2, 5));           // covered half of b
  EXPECT_TRUE(same({1, 1, 1}, g, 18 + 7, 5));           // uncovered half shows background
}

TEST(Figure, GridRowsAndCaptions) {
  Image p(20, 10, 3, 0.f);
  GridStyle s;
  s.columns = 2;
  Image g = grid({{p, "a"}, {p, "b"}, {p, "c"}}, s);
  int cap = text_size("Ag", s.caption_size)[1] + s.padding / 2;
  EXPECT_EQ(g.width, s.padding + 2 * (20 + s.padding));
  EXPECT_EQ(g.height, s.padding + 2 * (10 + cap + s.padding));
  // A caption wider than its panel widens every cell.
  Image wide = grid({{p, "a much longer caption"}, {p, "b"}}, s);
  EXPECT_EQ(wide.width, s.padding + 2 * (text_size("a much longer caption", s.caption_size)[0] + s.padding + s.padding));
  s.row_labels = {"one"};
  EXPECT_THROW(grid({{p, "a"}, {p, "b"}, {p, "c"}}, s), std::runtime_error);  // 2 rows, 1 label
}

// A title wider than the cells widens the figure (it was cut at both ends), the cells centred.
TEST(Figure, GridIsAsWideAsItsTitle) {
  Image p(20, 10, 3, 0.f);
  GridStyle s;
  s.background = {1, 1, 1};
  s.title = "a title far wider than the one panel under it";
  Image g = grid({{p, ""}}, s);
  const int title_w = text_size(s.title, s.title_size)[0];
  EXPECT_EQ(g.width, title_w + 2 * s.padding);
  const int title_h = text_size(s.title, s.title_size)[1] + s.padding;
  const int x0 = (g.width - (s.padding + 20 + s.padding)) / 2 + s.padding, y0 = s.padding + title_h;
  EXPECT_TRUE(same({0, 0, 0}, g, x0, y0 + 5) && same({0, 0, 0}, g, x0 + 19, y0 + 5));  // the panel, centred
  EXPECT_TRUE(same({1, 1, 1}, g, x0 - 1, y0 + 5) && same({1, 1, 1}, g, x0 + 20, y0 + 5));
  // Dark text reaches near both edges: none of it was cut.
  auto inked = [&](int x0_, int x1_) {
    for (int y = 0; y < title_h; ++y)
      for (int x = x0_; x < x1_; ++x)
        if (g.at(x, y, 0) < 0.5f) return true;
    return false;
  };
  EXPECT_TRUE(inked(0, s.padding + 8) && inked(g.width - s.padding - 8, g.width));
}

TEST(Figure, ColormapEndsAndMiddle) {
  Color lo = colormap(Colormap::inferno, 0), hi = colormap(Colormap::inferno, 1);
  EXPECT_NEAR(lo[0], 0x00 / 255.0, 1e-6);
  EXPECT_NEAR(lo[2], 0x04 / 255.0, 1e-6);
  EXPECT_NEAR(hi[0], 0xfc / 255.0, 1e-6);
  EXPECT_NEAR(hi[2], 0xa4 / 255.0, 1e-6);
  // t = 0.5 lies halfway between samples 4 (0xa52c60) and 5 (0xcf4446).
  Color mid = colormap(Colormap::inferno, 0.5);
  EXPECT_NEAR(mid[0], (0xa5 + 0xcf) / 2.0 / 255.0, 1e-6);
  Color g = colormap(Colormap::gray, 0.3);
  EXPECT_NEAR(g[1], 0.3, 1e-6);
  EXPECT_THROW(parse_colormap("jet"), std::runtime_error);
}

TEST(Figure, HeatmapMapsValuesAndMarksNaN) {
  Image d(4, 2, 3, 0.f);
  // Per-pixel value = mean |channel| over RGB.
  for (int k = 0; k < 3; ++k) d.at(1, 0, k) = 0.1f;                // 0.1
  d.at(2, 0, 0) = -0.3f;                                           // 0.1 (abs, mean of 3)
  for (int k = 0; k < 3; ++k) d.at(3, 0, k) = 0.4f;                // 0.4 > max: saturates
  d.at(0, 1, 1) = std::nanf("");
  Image mask(4, 2, 4, 1.f);
  mask.at(3, 1, 3) = 0.f;  // not covered
  HeatmapStyle s;
  s.max = 0.2;
  s.mask = &mask;
  Heatmap h = heatmap(d, s);
  EXPECT_NEAR(heat_value(d, 2, 0), 0.1, 1e-7);  // float storage
  EXPECT_EQ(h.non_finite, 1);
  EXPECT_TRUE(same(colormap(Colormap::inferno, 0), h.image, 0, 0));
  EXPECT_TRUE(same(colormap(Colormap::inferno, 0.5), h.image, 1, 0, 1e-4f));
  EXPECT_TRUE(same(colormap(Colormap::inferno, 0.5), h.image, 2, 0, 1e-4f));
  EXPECT_TRUE(same(colormap(Colormap::inferno, 1), h.image, 3, 0));
  EXPECT_TRUE(same({1, 0, 1}, h.image, 0, 1));  // NaN: magenta
  EXPECT_TRUE(same({1, 1, 1}, h.image, 3, 1));  // masked: background
  EXPECT_GT(h.image.width, d.width);          // colour bar beside
}

TEST(Figure, HeatmapAutoMaxAndColourBar) {
  Image d(40, 60, 1, 0.f);
  d.at(5, 5, 0) = 0.5f;
  d.at(6, 5, 0) = INFINITY;  // ignored by the automatic max, counted
  HeatmapStyle s;
  Heatmap h = heatmap(d, s);
  EXPECT_DOUBLE_EQ(h.max, 0.5);
  EXPECT_EQ(h.non_finite, 1);
  // The bar starts 6 px right of the image; its top row is the colormap's top, bottom its bottom.
  int bx = d.width + 6 + 5;
  int top = -1, bottom = -1;
  for (int y = 0; y < h.image.height; ++y) {
    bool bar = !same({1, 1, 1}, h.image, bx, y);
    if (bar && top < 0) top = y;
    if (bar) bottom = y;
  }
  ASSERT_GE(top, 0);
  EXPECT_TRUE(same(colormap(Colormap::inferno, 1), h.image, bx, top));
  EXPECT_TRUE(same(colormap(Colormap::inferno, 0), h.image, bx, bottom));
  EXPECT_GT(bottom - top, 30);
}

TEST(Figure, CropAndCoveredBox) {
  Image img(10, 8, 4, 0.f);
  for (int y = 2; y <= 5; ++y)
    for (int x = 3; x <= 6; ++x) img.at(x, y, 3) = 1.f, img.at(x, y, 0) = float(x) + 10.f * float(y);
  Box b = covered_box(img);
  EXPECT_EQ(b.x, 3);
  EXPECT_EQ(b.y, 2);
  EXPECT_EQ(b.width, 4);
  EXPECT_EQ(b.height, 4);
  Image c = crop(img, b.x, b.y, b.width, b.height);
  EXPECT_EQ(c.width, 4);
  EXPECT_EQ(c.at(0, 0, 0), 3.f + 20.f);
  EXPECT_EQ(c.at(3, 3, 0), 6.f + 50.f);
  EXPECT_THROW(crop(img, 8, 0, 4, 2), std::runtime_error);  // leaves the image
  EXPECT_EQ(covered_box(Image(3, 3, 4, 0.f)).width, 0);      // nothing covered
}

TEST(Figure, ClampKeepsAlphaAndNaN) {
  Image img(2, 1, 4, 0.f);
  img.at(0, 0, 0) = 3.f, img.at(0, 0, 1) = -1.f, img.at(0, 0, 2) = 0.25f, img.at(0, 0, 3) = 7.f;
  img.at(1, 0, 0) = std::nanf("");
  Image c = clamp_colors(img);
  EXPECT_EQ(c.at(0, 0, 0), 1.f);
  EXPECT_EQ(c.at(0, 0, 1), 0.f);
  EXPECT_EQ(c.at(0, 0, 2), 0.25f);
  EXPECT_EQ(c.at(0, 0, 3), 7.f);  // alpha untouched
  EXPECT_TRUE(std::isnan(c.at(1, 0, 0)));
  // Every channel count (each has its own loop): colour channels 1..3 clamped to [lo, hi], the
  // others as they were, infinities included.
  for (int channels = 1; channels <= 5; ++channels) {
    Image m(7, 3, channels);
    for (std::size_t i = 0; i < m.pixels.size(); ++i) m.pixels[i] = float(int(i % 11) - 4) * 0.3f;
    m.at(6, 2, channels - 1) = INFINITY;
    Image got = clamp_colors(m, -0.5f, 0.7f);
    for (std::size_t i = 0; i < m.pixels.size(); ++i) {
      const float v = m.pixels[i];
      const float want = int(i % std::size_t(channels)) < 3 ? std::min(0.7f, std::max(-0.5f, v)) : v;
      ASSERT_EQ(got.pixels[i], want) << channels << " channels, float " << i;
    }
  }
}

// The coverage figure: two equal-area maps drawn pixel by pixel (each pixel shows the bin its
// centre falls in, so any bands x sectors resolution draws without a special case), with io/'s
// text and colormaps for the labels, the colour bar and the legend.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "data/coverage.h"
#include "io/figure.h"

namespace sn::data {

namespace {

// One fixed layout: the figure's size depends on nothing but the text, so scripts and tests
// can rely on it. Both maps use kUnit pixels per unit of cos and kMapW pixels per 2pi, so a page
// area is the same solid angle in either map.
constexpr int kMapW = 576, kUnit = 144;
constexpr int kPad = 16, kTitleH = 34, kCaptionH = 24, kYLabelW = 22, kYTicksW = 40;
constexpr int kLeft = kPad + kYLabelW + kYTicksW;            // normal map's left edge
constexpr int kTop = kPad + kTitleH + kCaptionH;             // both maps' top edge
constexpr int kGap = kYLabelW + kYTicksW + 24;               // between the maps
constexpr int kViewLeft = kLeft + kMapW + kGap;
constexpr int kBarLeft = kViewLeft + kMapW + 36, kBarW = 16;
constexpr int kWidth = kBarLeft + kBarW + 70 + kPad;
constexpr int kXTicksH = 20, kXLabelH = 22;
constexpr int kHeight = kTop + 2 * kUnit + kXTicksH + kXLabelH + kPad;

constexpr float kTick = 13, kLabel = 14, kCaption = 16, kTitle = 20;
const io::Color kBlack{0, 0, 0}, kUncovered{0.80f, 0.80f, 0.80f}, kOtherOnly{0.90f, 0.10f, 0.10f},
    kGrid{1, 1, 1};

void put(io::Image& img, int x, int y, const io::Color& c) {
  if (x < 0 || y < 0 || x >= img.width || y >= img.height) return;
  for (int k = 0; k < 3; ++k) img.at(x, y, k) = c[k];
}

void rect(io::Image& img, int x, int y, int w, int h, const io::Color& c) {
  for (int j = y; j < y + h; ++j)
    for (int i = x; i < x + w; ++i) put(img, i, j, c);
}

void frame(io::Image& img, int x, int y, int w, int h) {
  rect(img, x - 1, y - 1, w + 2, 1, kBlack);
  rect(img, x - 1, y + h, w + 2, 1, kBlack);
  rect(img, x - 1, y, 1, h, kBlack);
  rect(img, x + w, y, 1, h, kBlack);
}

void text(io::Image& img, int x, int y, const std::string& s, float size, io::Align a = io::Align::left) {
  io::draw_text(img, x, y, s, {size, kBlack, a});
}

// Text turned a quarter left (reading upwards), centred on (cx, cy): draw_text cannot rotate,
// so it draws into a transparent image that is turned and composited.
void text_up(io::Image& img, int cx, int cy, const std::string& s, float size) {
  auto [w, h] = io::text_size(s, size);
  if (w < 1) return;
  io::Image t(w, h, 4, 0.f);
  io::draw_text(t, 0, 0, s, {size, kBlack, io::Align::left});
  const int x0 = cx - h / 2, y0 = cy - w / 2;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float a = std::clamp(t.at(x, y, 3), 0.f, 1.f);
      const int dx = x0 + y, dy = y0 + (w - 1 - x);
      if (a <= 0 || dx < 0 || dy < 0 || dx >= img.width || dy >= img.height) continue;
      for (int k = 0; k < 3; ++k) img.at(dx, dy, k) = t.at(x, y, k) * a + img.at(dx, dy, k) * (1 - a);
    }
}

std::string fixed(double v, int digits) {
  char b[32];
  std::snprintf(b, sizeof b, "%.*f", digits, v);
  return b;
}

std::string percent(double f) { return fixed(100 * f, 1) + "%"; }

// Colour scale: log(count) from min_count (bottom) to the largest count (top).
struct LogScale {
  double lo, hi;
  double at(double c) const { return hi > lo ? (std::log(c) - std::log(lo)) / (std::log(hi) - std::log(lo)) : 1.0; }
};

struct MapSpec {
  int left, top, height;  // pixels; the width is kMapW
  int bands, sectors;
  double y_lo;  // the value of the bottom edge (-1 for normals, 0 for views); the top is 1
  const std::vector<uint32_t>* mine;
  const std::vector<uint32_t>* other;  // may be null
};

void draw_map(io::Image& img, const MapSpec& m, int min_count, const LogScale& scale) {
  auto bin_at = [&](int px, int py) {
    const double u = (px + 0.5) / kMapW, y = 1 - (py + 0.5) / m.height * (1 - m.y_lo);
    const int band = std::clamp(int(std::floor((y - m.y_lo) / (1 - m.y_lo) * m.bands)), 0, m.bands - 1);
    const int sector = std::clamp(int(std::floor(u * m.sectors)), 0, m.sectors - 1);
    return band * m.sectors + sector;
  };
  // Bin borders as thin white lines while the cells are big enough to keep their colour readable.
  const bool grid = kMapW / m.sectors >= 5 && m.height / m.bands >= 5;
  for (int py = 0; py < m.height; ++py)
    for (int px = 0; px < kMapW; ++px) {
      const int b = bin_at(px, py);
      io::Color c;
      const uint32_t n = (*m.mine)[std::size_t(b)];
      if (n >= uint32_t(min_count)) c = io::colormap(io::Colormap::viridis, scale.at(n));
      else if (m.other && (*m.other)[std::size_t(b)] > 0) c = kOtherOnly;
      else c = kUncovered;
      if (grid && ((px > 0 && bin_at(px - 1, py) != b) || (py > 0 && bin_at(px, py - 1) != b))) c = kGrid;
      put(img, m.left + px, m.top + py, c);
    }
  frame(img, m.left, m.top, kMapW, m.height);
  // Axes: phi / psi in degrees across, cos up.
  for (int deg = 0; deg <= 360; deg += 90) {
    const int x = m.left + int(std::lround(deg / 360.0 * (kMapW - 1)));
    rect(img, x, m.top + m.height + 1, 1, 4, kBlack);
    text(img, x, m.top + m.height + 5, std::to_string(deg), kTick, io::Align::center);
  }
  for (double y = 1; y >= m.y_lo - 1e-9; y -= 0.5) {
    const int py = m.top + int(std::lround((1 - y) / (1 - m.y_lo) * (m.height - 1)));
    rect(img, m.left - 5, py, 4, 1, kBlack);
    const int th = io::text_size("0", kTick)[1];
    text(img, m.left - 7, std::clamp(py - th / 2, m.top - 2, m.top + m.height - th + 2), fixed(y, 1), kTick,
         io::Align::right);
  }
}

}  // namespace

io::Image coverage_figure(const Histogram& mine, const Histogram* other, const CoverageFigure& f) {
  const BinScheme& s = mine.scheme;
  if (other && (other->scheme.normal_bins() != s.normal_bins() || other->scheme.view_bins() != s.view_bins()))
    throw std::invalid_argument("coverage figure: the two histograms use different bin schemes");
  io::Image img(kWidth, kHeight, 3, 1.f);
  uint32_t hi = 0;
  for (const auto* v : {&mine.normal, &mine.view})
    for (uint32_t c : *v) hi = std::max(hi, c);
  const LogScale scale{double(f.min_count), std::max(double(f.min_count), double(hi))};

  text(img, kWidth / 2, kPad, f.title, kTitle, io::Align::center);
  const std::size_t nc = covered_bins(mine.normal, f.min_count), vc = covered_bins(mine.view, f.min_count);
  text(img, kLeft + kMapW / 2, kPad + kTitleH,
       "normals (sphere): " + std::to_string(nc) + " of " + std::to_string(s.normal_bins()) + " bins covered, " +
           percent(double(nc) / s.normal_bins()),
       kCaption, io::Align::center);
  text(img, kViewLeft + kMapW / 2, kPad + kTitleH,
       "views (hemisphere about n): " + std::to_string(vc) + " of " + std::to_string(s.view_bins()) +
           " bins covered, " + percent(double(vc) / s.view_bins()),
       kCaption, io::Align::center);

  const MapSpec normal{kLeft, kTop, 2 * kUnit, s.normal_bands, s.normal_sectors, -1, &mine.normal,
                       other ? &other->normal : nullptr};
  const MapSpec view{kViewLeft, kTop, kUnit, s.view_bands, s.view_sectors, 0, &mine.view,
                     other ? &other->view : nullptr};
  draw_map(img, normal, f.min_count, scale);
  draw_map(img, view, f.min_count, scale);
  text_up(img, kPad + kYLabelW / 2, kTop + kUnit, "y = cos theta  (theta from world +y)", kLabel);
  text_up(img, kViewLeft - kYTicksW - kYLabelW / 2, kTop + kUnit / 2, "cos theta_v = n.v", kLabel);
  text(img, kLeft + kMapW / 2, kTop + 2 * kUnit + kXTicksH, "phi = atan2(z, x)  [degrees]", kLabel,
       io::Align::center);
  text(img, kViewLeft + kMapW / 2, kTop + kUnit + kXTicksH,
       "view azimuth from world +y projected onto the surface  [degrees]", kLabel, io::Align::center);

  // Legend and numbers in the room under the (half as tall) view map.
  const int line = io::text_size("Ag", kLabel)[1] + 6;
  int y = kTop + kUnit + kXTicksH + kXLabelH + 10;
  auto swatch = [&](const io::Color& c, const std::string& what) {
    rect(img, kViewLeft, y + 2, 14, 14, c);
    frame(img, kViewLeft, y + 2, 14, 14);
    text(img, kViewLeft + 22, y, what, kLabel);
    y += line;
  };
  for (int i = 0; i < 14; ++i) rect(img, kViewLeft + i, y + 2, 1, 14, io::colormap(io::Colormap::viridis, i / 13.0));
  frame(img, kViewLeft, y + 2, 14, 14);
  text(img, kViewLeft + 22, y,
       "covered (at least " + std::to_string(f.min_count) + (f.min_count == 1 ? " row" : " rows") +
           "): colour = rows in the bin, log scale",
       kLabel);
  y += line;
  swatch(kUncovered, f.min_count == 1 ? "uncovered: no rows"
                                      : "uncovered: fewer than " + std::to_string(f.min_count) + " rows");
  if (other) swatch(kOtherOnly, "uncovered here, but " + f.against + " has rows there");
  y += 4;
  text(img, kViewLeft, y,
       std::to_string(mine.rows) + " rows; normals' y from " + fixed(mine.normal_y_min, 2) + " to " +
           fixed(mine.normal_y_max, 2) + (mine.below_horizon ? "; " + std::to_string(mine.below_horizon) +
                                                                   " views below the horizon"
                                                             : ""),
       kLabel);

  // Colour bar beside the view map: rows per bin on the log scale, ticks at the ends and powers of ten.
  const int bar_top = kTop, bar_h = 2 * kUnit;
  for (int j = 0; j < bar_h; ++j)
    rect(img, kBarLeft, bar_top + j, kBarW, 1, io::colormap(io::Colormap::viridis, 1 - double(j) / (bar_h - 1)));
  frame(img, kBarLeft, bar_top, kBarW, bar_h);
  text(img, kBarLeft + kBarW / 2, bar_top - kCaptionH + 2, "rows / bin", kTick, io::Align::center);
  const int th = io::text_size("0", kTick)[1];
  auto tick = [&](double c) {
    const int py = bar_top + int(std::lround((1 - scale.at(c)) * (bar_h - 1)));
    rect(img, kBarLeft + kBarW + 1, py, 4, 1, kBlack);
    text(img, kBarLeft + kBarW + 7, py - th / 2, std::to_string((long long)std::llround(c)), kTick);
    return py;
  };
  int last_lo = tick(scale.lo), last_hi = scale.hi > scale.lo ? tick(scale.hi) : -1000;
  for (double p = 10; p < scale.hi; p *= 10) {
    if (p <= scale.lo) continue;
    const int py = bar_top + int(std::lround((1 - scale.at(p)) * (bar_h - 1)));
    if (std::abs(py - last_lo) > th && std::abs(py - last_hi) > th) tick(p);
  }
  return img;
}

}  // namespace sn::data

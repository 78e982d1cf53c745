#include "io/overlay.h"

#include <algorithm>
#include <cmath>

namespace sn::io {

namespace {

Image background(int w, int h, const OverlayStyle& s) {
  Image img(w, h, 4);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      for (int k = 0; k < 3; ++k) img.at(x, y, k) = s.background[k];
      img.at(x, y, 3) = s.opacity;
    }
  return img;
}

}  // namespace

std::string fit_text(const std::string& text, int width, float size) {
  if (text_size(text, size)[0] <= width) return text;
  // Binary search on the byte length; a cut never splits a UTF-8 character.
  size_t lo = 0, hi = text.size();
  while (lo < hi) {
    size_t mid = (lo + hi + 1) / 2;
    while (mid > 0 && mid < text.size() && (static_cast<unsigned char>(text[mid]) & 0xC0) == 0x80) --mid;
    if (mid <= lo) break;
    if (text_size(text.substr(0, mid) + "...", size)[0] <= width) lo = mid;
    else hi = mid - 1;
  }
  return text.substr(0, lo) + "...";
}

Image text_box(const std::vector<OverlayLine>& lines, int width, const OverlayStyle& s) {
  int line_h = text_size("Ag", s.size)[1];
  if (width <= 0)
    for (const auto& l : lines) width = std::max(width, text_size(l.text, s.size)[0] + 2 * s.padding);
  width = std::max(width, 2 * s.padding + 1);
  int h = int(lines.size()) * (line_h + s.padding) + s.padding;
  Image img = background(width, h, s);
  int y = s.padding;
  for (const auto& l : lines) {
    TextStyle ts;
    ts.size = s.size, ts.color = l.color;
    draw_text(img, s.padding, y, fit_text(l.text, width - 2 * s.padding, s.size), ts);
    y += line_h + s.padding;
  }
  return img;
}

Image progress_bar(double fraction, const std::string& text, int width, Color fill, const OverlayStyle& s) {
  int h = text_size("Ag", s.size)[1] + 2 * s.padding;
  width = std::max(width, 1);
  Image img = background(width, h, s);
  double f = std::isfinite(fraction) ? std::clamp(fraction, 0.0, 1.0) : 0.0;
  int filled = int(std::lround(f * width));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < filled; ++x) {
      for (int k = 0; k < 3; ++k) img.at(x, y, k) = fill[k];
      img.at(x, y, 3) = 1;
    }
  TextStyle ts;
  ts.size = s.size, ts.align = Align::center;
  draw_text(img, width / 2, s.padding, fit_text(text, width - 2 * s.padding, s.size), ts);
  return img;
}

}  // namespace sn::io

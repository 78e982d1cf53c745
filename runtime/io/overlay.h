// Pictures live mode draws over its view: a box of text lines (an error, a counter, a label)
// and a progress bar. RGBA images with a translucent background; the window blends them over
// the last picture (gl/overlay.h). Text is drawn as the figures' labels are (io/figure.h).
#pragma once
#include <string>
#include <vector>

#include "io/figure.h"
#include "io/image.h"

namespace sn::io {

struct OverlayLine {
  std::string text;
  Color color{1, 1, 1};
};

struct OverlayStyle {
  float size = 14;  // pixel height of the font
  int padding = 5;  // around and between the lines
  Color background{0, 0, 0};
  float opacity = 0.75f;  // of the background; glyphs are opaque
};

// The lines, one under the other, in a box `width` pixels wide (0: as wide as the longest
// line). A line too long for the box is cut and ends in "...", so a long message never runs
// off the window.
Image text_box(const std::vector<OverlayLine>& lines, int width, const OverlayStyle& style = {});

// A bar `width` pixels wide: `fraction` (clamped to 0..1) of it filled with `fill`, `text`
// centred on it.
Image progress_bar(double fraction, const std::string& text, int width, Color fill = {0.2f, 0.55f, 0.95f},
                   const OverlayStyle& style = {});

// `text` cut to at most `width` pixels at `size`, ending in "..." when it was cut.
std::string fit_text(const std::string& text, int width, float size);

}  // namespace sn::io

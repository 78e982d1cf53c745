// Figures a paper would show, composed from float images: text labels (OpenImageIO's
// render_text with a DejaVu font), labelled grids of panels, and error heatmaps with a colour
// bar. Everything works on io::Image; pixel values stay linear floats in [0, 1].
#pragma once
#include <array>
#include <string>
#include <vector>

#include "io/image.h"

namespace sn::io {

using Color = std::array<float, 3>;

enum class Align { left, center, right };

struct TextStyle {
  float size = 16;  // pixel height of the font
  Color color{1, 1, 1};
  Align align = Align::left;  // of x: the text's left edge, centre or right edge
};

// The font every label uses; throws naming the Debian package to install when none is found.
const std::string& label_font();
// Width and height in pixels of `text` drawn at `size` (height = the font's line: ascent + descent).
std::array<int, 2> text_size(const std::string& text, float size);
// Labels are UTF-8; OpenImageIO 2.4 draws bytes, so common punctuation (dashes, x, degree,
// arrows, quotes) is drawn in its ASCII spelling and any other non-ASCII character as '?'.
// Draws `text` with the top of its line at row y; x per style.align. Writes the first
// min(3, channels) channels; a 4th (alpha) channel is set to 1 under the glyphs.
void draw_text(Image& img, int x, int y, const std::string& text, const TextStyle& style = {});

struct Panel {
  Image image;
  std::string caption;  // drawn under the panel; may be empty
};

struct GridStyle {
  int columns = 0;  // 0 = all panels in one row
  int padding = 6;  // pixels between panels and around the grid
  float caption_size = 14;
  float title_size = 18;
  std::string title;  // above the grid; may be empty
  std::vector<std::string> row_labels;  // left of each row; empty = none
  Color background{1, 1, 1};
  Color text{0, 0, 0};
};

// Lays panels out in rows of `columns`, each in a cell as large as the largest panel, captions
// centred under them. RGBA panels are composited over the background by their alpha (coverage),
// 1- and 2-channel panels are shown as grey. The result has 3 channels.
Image grid(const std::vector<Panel>& panels, const GridStyle& style);

// `img` with the first min(3, channels) channels clamped to [lo, hi], as a display shows them;
// NaN stays NaN (a broken pixel must stay visible), alpha is kept. (Pass a temporary, and no copy is made.)
Image clamp_colors(Image img, float lo = 0.f, float hi = 1.f);

// The part of `img` at (x, y) of size w x h (0-based, top-left); throws when it leaves the image.
Image crop(const Image& img, int x, int y, int w, int h);

struct Box {
  int x = 0, y = 0, width = 0, height = 0;  // 0-based, top-left; width 0 = nothing covered
};
// The smallest box holding every pixel whose `channel` is > 0.5 (a render's coverage).
Box covered_box(const Image& img, int channel = 3);

enum class Colormap { inferno, viridis, gray };
const char* colormap_name(Colormap c);
Colormap parse_colormap(const std::string& name);  // throws listing the valid names
// The colormap at t in [0, 1] (clamped).
Color colormap(Colormap c, double t);

struct HeatmapStyle {
  double max = 0;  // value mapped to the top of the colour bar; <= 0: the image's largest value
  Colormap map = Colormap::inferno;
  bool colorbar = true;
  std::string label;  // under the colour bar's ticks, e.g. "|error|"
  const Image* mask = nullptr;  // pixels whose mask channel is <= 0.5 are drawn as background
  int mask_channel = 3;
  Color background{1, 1, 1};
  Color text{0, 0, 0};
  Color non_finite{1, 0, 1};  // NaN / Inf pixels: never hidden, shown in magenta
};

struct Heatmap {
  Image image;  // 3 channels; wider than the input by the colour bar
  double max = 0;  // the value at the top of the colour bar
  long long non_finite = 0;  // pixels that were NaN or Inf
};

// One value per pixel: the mean over the first min(3, channels) channels of |value|, mapped
// through the colormap from 0 to max (values above max saturate), with a labelled colour bar.
Heatmap heatmap(const Image& diff, const HeatmapStyle& style);
// The per-pixel value heatmap() maps (exposed for tests and scripts).
double heat_value(const Image& diff, int x, int y);

}  // namespace sn::io

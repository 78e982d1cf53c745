#include "io/figure.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "io/image_codec.h"

namespace sn::io {

namespace {

// OpenImageIO's default font (DroidSans) is not packaged by Debian; DejaVu is
// (fonts-dejavu-core), found by name in the system font folders or by path.
const char* const kFontCandidates[] = {"DejaVuSans", "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
                                       "/usr/share/fonts/TTF/DejaVuSans.ttf"};

struct LineMetrics {
  int ascent, descent;
};

LineMetrics line_metrics(float size) {
  // Glyphs reaching the highest and lowest: every line gets the same height, whatever it says.
  const TextBox r = image_codec().text_size("AHg|(", int(std::lround(size)), label_font());
  return {std::max(1, -r.y0), std::max(0, r.y1)};
}

void fill(Image& img, const Color& c) {
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      for (int k = 0; k < img.channels; ++k) img.at(x, y, k) = k < 3 ? c[k] : 1.f;
}

// Copies `src` into the RGB image `dst` at (ox, oy), compositing RGBA over what is there.
void blit(Image& dst, const Image& src, int ox, int oy) {
  for (int y = 0; y < src.height; ++y) {
    int dy = oy + y;
    if (dy < 0 || dy >= dst.height) continue;
    for (int x = 0; x < src.width; ++x) {
      int dx = ox + x;
      if (dx < 0 || dx >= dst.width) continue;
      float rgb[3];
      if (src.channels >= 3) {
        for (int k = 0; k < 3; ++k) rgb[k] = src.at(x, y, k);
      } else {
        rgb[0] = rgb[1] = rgb[2] = src.at(x, y, 0);
      }
      float a = src.channels == 4 ? std::clamp(src.at(x, y, 3), 0.f, 1.f) : 1.f;
      for (int k = 0; k < 3; ++k) dst.at(dx, dy, k) = rgb[k] * a + dst.at(dx, dy, k) * (1 - a);
    }
  }
}

std::string tick_label(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

// Matplotlib's palettes sampled at 10 evenly spaced points (t = i / 9), interpolated linearly.
constexpr unsigned kInferno[10] = {0x000004, 0x1b0c41, 0x4a0c6b, 0x781c6d, 0xa52c60,
                                   0xcf4446, 0xed6925, 0xfb9b06, 0xf7d13d, 0xfcffa4};
constexpr unsigned kViridis[10] = {0x440154, 0x482878, 0x3e4989, 0x31688e, 0x26828e,
                                   0x1f9e89, 0x35b779, 0x6ece58, 0xb5de2b, 0xfde725};

Color hex(unsigned c) { return {((c >> 16) & 255) / 255.f, ((c >> 8) & 255) / 255.f, (c & 255) / 255.f}; }

// OpenImageIO 2.4's render_text draws bytes, not UTF-8 characters ("—" comes out as three
// boxes), so labels are made ASCII first: the punctuation figures use gets its usual ASCII
// spelling, anything else becomes '?' (visible, never silently dropped).
std::string ascii_label(const std::string& text) {
  struct Sub {
    const char* utf8;
    const char* ascii;
  };
  static const Sub subs[] = {{"\u2014", "-"},  {"\u2013", "-"},  {"\u2212", "-"},   {"\u00d7", "x"},
                             {"\u00b0", " deg"}, {"\u2192", "->"}, {"\u2190", "<-"}, {"\u00b5", "u"},
                             {"\u03bc", "u"},   {"\u2018", "'"},  {"\u2019", "'"},   {"\u201c", "\""},
                             {"\u201d", "\""},  {"\u2026", "..."}, {"\u00b2", "^2"},  {"\u00e9", "e"}};
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    unsigned char c = static_cast<unsigned char>(text[i]);
    if (c < 0x80) {
      out += char(c);
      ++i;
      continue;
    }
    std::size_t len = c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : c >= 0xC0 ? 2 : 1;
    std::string ch = text.substr(i, len);
    const char* rep = "?";
    for (const Sub& sub : subs)
      if (ch == sub.utf8) rep = sub.ascii;
    out += rep;
    i += len;
  }
  return out;
}

}  // namespace

const std::string& label_font() {
  static const std::string font = [] {
    for (const char* f : kFontCandidates)
      if (image_codec().text_size("Ag", 16, f).defined) return std::string(f);
    return std::string();
  }();
  if (font.empty())
    throw std::runtime_error(
        "no font for figure labels: OpenImageIO found none of DejaVuSans, "
        "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf (install the Debian package fonts-dejavu-core)");
  return font;
}

std::array<int, 2> text_size(const std::string& utf8, float size) {
  const std::string text = ascii_label(utf8);
  if (!(size >= 1 && size <= 512)) throw std::runtime_error("text size must be 1..512 pixels, got " + std::to_string(size));
  LineMetrics m = line_metrics(size);
  if (text.empty()) return {0, m.ascent + m.descent};
  const TextBox r = image_codec().text_size(text, int(std::lround(size)), label_font());
  return {r.defined ? r.x1 - std::min(0, r.x0) : 0, m.ascent + m.descent};
}

void draw_text(Image& img, int x, int y, const std::string& utf8, const TextStyle& style) {
  const std::string text = ascii_label(utf8);
  if (text.empty()) return;
  auto [w, h] = text_size(text, style.size);
  // In 64 bits: x and y may be anywhere in int's range.
  const long long x0 = style.align == Align::left ? x : style.align == Align::center ? x - w / 2LL : x - (long long)w;
  // Text wholly outside the image draws nothing (OpenImageIO asserts on such a region).
  if (x0 >= img.width || x0 + w <= 0 || y >= img.height || (long long)y + h <= 0) return;
  int baseline = y + line_metrics(style.size).ascent;
  std::vector<float> color(img.channels, 1.f);
  for (int k = 0; k < std::min(3, img.channels); ++k) color[k] = style.color[k];
  std::string error;
  if (!image_codec().render_text(img, int(x0), baseline, text, int(std::lround(style.size)), label_font(), color, &error))
    throw std::runtime_error("cannot draw text '" + text + "': " + error);
}

Image grid(const std::vector<Panel>& panels, const GridStyle& s) {
  if (panels.empty()) throw std::runtime_error("grid: no panels");
  if (s.columns < 0) throw std::runtime_error("grid: columns must be >= 0, got " + std::to_string(s.columns));
  if (s.padding < 0 || s.padding > 256) throw std::runtime_error("grid: padding must be 0..256");
  int n = int(panels.size());
  int cols = s.columns == 0 ? n : std::min(s.columns, n);
  int rows = (n + cols - 1) / cols;
  if (!s.row_labels.empty() && int(s.row_labels.size()) != rows)
    throw std::runtime_error("grid: " + std::to_string(s.row_labels.size()) + " row labels for " +
                             std::to_string(rows) + " rows");
  int cell_w = 0, cell_h = 0;
  bool captions = false;
  for (const Panel& p : panels) {
    if (p.image.width < 1 || p.image.channels < 1) throw std::runtime_error("grid: a panel is an empty image");
    cell_w = std::max(cell_w, p.image.width);
    cell_h = std::max(cell_h, p.image.height);
    captions = captions || !p.caption.empty();
  }
  int pad = s.padding;
  // A cell is also as wide as the longest caption, so neighbouring captions never overlap.
  for (const Panel& p : panels)
    if (!p.caption.empty()) cell_w = std::max(cell_w, text_size(p.caption, s.caption_size)[0] + pad);
  int cap_h = captions ? text_size("Ag", s.caption_size)[1] + pad / 2 : 0;
  int title_h = s.title.empty() ? 0 : text_size(s.title, s.title_size)[1] + pad;
  int label_w = 0;
  for (const auto& l : s.row_labels) label_w = std::max(label_w, text_size(l, s.caption_size)[0] + pad);
  const int content_w = pad + label_w + cols * (cell_w + pad);
  // As wide as the title too (it was cut at both ends), the cells centred under it.
  const int W = std::max(content_w, s.title.empty() ? 0 : text_size(s.title, s.title_size)[0] + 2 * pad);
  const int ox = (W - content_w) / 2;
  int H = pad + title_h + rows * (cell_h + cap_h + pad);
  Image out(W, H, 3);
  fill(out, s.background);
  TextStyle caption{s.caption_size, s.text, Align::center};
  if (!s.title.empty()) draw_text(out, W / 2, pad, s.title, {s.title_size, s.text, Align::center});
  for (int i = 0; i < n; ++i) {
    int r = i / cols, c = i % cols;
    int cx = ox + pad + label_w + c * (cell_w + pad), cy = pad + title_h + r * (cell_h + cap_h + pad);
    const Image& img = panels[size_t(i)].image;
    blit(out, img, cx + (cell_w - img.width) / 2, cy + (cell_h - img.height) / 2);
    draw_text(out, cx + cell_w / 2, cy + cell_h + pad / 2, panels[size_t(i)].caption, caption);
  }
  for (int r = 0; r < int(s.row_labels.size()); ++r) {
    int cy = pad + title_h + r * (cell_h + cap_h + pad) + cell_h / 2 - text_size("Ag", s.caption_size)[1] / 2;
    draw_text(out, ox + pad, cy, s.row_labels[size_t(r)], {s.caption_size, s.text, Align::left});
  }
  return out;
}

namespace {
// Clamps channels [0, n) of `count` pixels of C channels; a constant C lets the loop vectorize.
// Branch-free; NaN stays NaN (both comparisons are false).
template <int C>
void clamp_pixels(float* px, std::size_t count, int n, float lo, float hi) {
  float l[C], h[C];  // the channels past n are left as they are: clamped to the whole line
  for (int k = 0; k < C; ++k)
    l[k] = k < n ? lo : -std::numeric_limits<float>::infinity(), h[k] = k < n ? hi : std::numeric_limits<float>::infinity();
  for (std::size_t p = 0; p < count; ++p)
    for (int k = 0; k < C; ++k) {
      const float v = px[p * C + k];
      px[p * C + k] = v < l[k] ? l[k] : h[k] < v ? h[k] : v;
    }
}
}  // namespace

Image clamp_colors(Image img, float lo, float hi) {
  if (!(lo <= hi)) throw std::runtime_error("clamp: lo must be <= hi");
  const int n = std::min(3, img.channels);
  const std::size_t count = std::size_t(img.width) * std::size_t(img.height);
  float* px = img.pixels.data();
  switch (img.channels) {
    case 1: clamp_pixels<1>(px, count, n, lo, hi); break;
    case 2: clamp_pixels<2>(px, count, n, lo, hi); break;
    case 3: clamp_pixels<3>(px, count, n, lo, hi); break;
    case 4: clamp_pixels<4>(px, count, n, lo, hi); break;
    default:
      for (std::size_t p = 0; p < count; ++p)
        for (int k = 0; k < n; ++k) {
          float& v = px[p * std::size_t(img.channels) + std::size_t(k)];
          v = v < lo ? lo : hi < v ? hi : v;
        }
  }
  return img;
}

Image crop(const Image& img, int x, int y, int w, int h) {
  if (w < 1 || h < 1 || x < 0 || y < 0 || x > img.width - w || y > img.height - h)  // no x + w: it may overflow
    throw std::runtime_error("crop: the box (" + std::to_string(x + 1) + ", " + std::to_string(y + 1) + ") size " +
                             std::to_string(w) + "x" + std::to_string(h) + " is not inside the " +
                             std::to_string(img.width) + "x" + std::to_string(img.height) + " image");
  Image out(w, h, img.channels);
  for (int r = 0; r < h; ++r)
    std::copy_n(&img.pixels[(size_t(y + r) * img.width + x) * img.channels], size_t(w) * img.channels,
                &out.pixels[size_t(r) * w * img.channels]);
  return out;
}

Box covered_box(const Image& img, int channel) {
  if (channel < 0 || channel >= img.channels)
    throw std::runtime_error("covered_box: channel " + std::to_string(channel + 1) + " outside 1.." +
                             std::to_string(img.channels));
  int x0 = img.width, y0 = img.height, x1 = -1, y1 = -1;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      if (img.at(x, y, channel) > 0.5f) {
        x0 = std::min(x0, x), x1 = std::max(x1, x);
        y0 = std::min(y0, y), y1 = std::max(y1, y);
      }
  if (x1 < 0) return {};
  return {x0, y0, x1 - x0 + 1, y1 - y0 + 1};
}

const char* colormap_name(Colormap c) {
  switch (c) {
    case Colormap::inferno: return "inferno";
    case Colormap::viridis: return "viridis";
    case Colormap::gray: return "gray";
  }
  return "?";
}

Colormap parse_colormap(const std::string& name) {
  for (Colormap c : {Colormap::inferno, Colormap::viridis, Colormap::gray})
    if (name == colormap_name(c)) return c;
  throw std::runtime_error("unknown colormap '" + name + "' (valid: inferno, viridis, gray)");
}

Color colormap(Colormap c, double t) {
  t = std::isfinite(t) ? std::clamp(t, 0.0, 1.0) : 0.0;
  if (c == Colormap::gray) return {float(t), float(t), float(t)};
  const unsigned* table = c == Colormap::inferno ? kInferno : kViridis;
  double f = t * 9;
  int i = std::min(8, int(f));
  double u = f - i;
  Color a = hex(table[i]), b = hex(table[i + 1]), out;
  for (int k = 0; k < 3; ++k) out[k] = float(a[k] * (1 - u) + b[k] * u);
  return out;
}

double heat_value(const Image& diff, int x, int y) {
  int n = std::min(3, diff.channels);
  double s = 0;
  for (int k = 0; k < n; ++k) s += std::fabs(double(diff.at(x, y, k)));
  return s / n;
}

Heatmap heatmap(const Image& diff, const HeatmapStyle& s) {
  if (diff.width < 1 || diff.channels < 1) throw std::runtime_error("heatmap: empty image");
  const Image* mask = s.mask;
  if (mask) {
    if (mask->width != diff.width || mask->height != diff.height)
      throw std::runtime_error("heatmap: mask is " + std::to_string(mask->width) + "x" + std::to_string(mask->height) +
                               ", image is " + std::to_string(diff.width) + "x" + std::to_string(diff.height));
    if (s.mask_channel < 0 || s.mask_channel >= mask->channels)
      throw std::runtime_error("heatmap: mask channel " + std::to_string(s.mask_channel + 1) + " outside 1.." +
                               std::to_string(mask->channels));
  }
  auto covered = [&](int x, int y) { return !mask || mask->at(x, y, s.mask_channel) > 0.5f; };
  Heatmap h;
  h.max = s.max;
  if (!(h.max > 0)) {
    h.max = 0;
    for (int y = 0; y < diff.height; ++y)
      for (int x = 0; x < diff.width; ++x) {
        double v = heat_value(diff, x, y);
        if (covered(x, y) && std::isfinite(v)) h.max = std::max(h.max, v);
      }
    if (h.max == 0) h.max = 1;  // an all-zero error: any scale shows it as 0
  }
  if (!std::isfinite(h.max)) throw std::runtime_error("heatmap: max must be finite");

  const float tick_size = std::clamp(diff.height / 10.f, 10.f, 14.f);
  const int bar_w = s.colorbar ? 12 : 0, gap = s.colorbar ? 6 : 0;
  std::vector<std::string> ticks = {tick_label(h.max), tick_label(h.max / 2), "0"};
  int tick_w = 0;
  if (s.colorbar)
    for (const auto& t : ticks) tick_w = std::max(tick_w, text_size(t, tick_size)[0]);
  int line_h = s.colorbar ? text_size("Ag", tick_size)[1] : 0;
  int label_h = s.colorbar && !s.label.empty() ? line_h + 2 : 0;
  int label_w = label_h ? text_size(s.label, tick_size)[0] : 0;
  int W = diff.width + (s.colorbar ? gap + bar_w + 4 + std::max(tick_w, label_w - bar_w - 4) + 4 : 0);
  // The colorbar's three tick labels need three text lines: a shorter image gets a taller canvas.
  int H = std::max(diff.height, s.colorbar ? 3 * line_h : 0) + label_h;
  h.image = Image(W, H, 3);
  fill(h.image, s.background);
  for (int y = 0; y < diff.height; ++y)
    for (int x = 0; x < diff.width; ++x) {
      if (!covered(x, y)) continue;
      double v = heat_value(diff, x, y);
      Color c = s.non_finite;
      if (std::isfinite(v)) c = colormap(s.map, v / h.max);
      else ++h.non_finite;
      for (int k = 0; k < 3; ++k) h.image.at(x, y + label_h, k) = c[k];
    }
  if (!s.colorbar) return h;
  // The bar spans the image's rows (less half a text line top and bottom, so its end labels fit).
  int bx = diff.width + gap, top = label_h + line_h / 2, bottom = H - 1 - line_h / 2;
  if (bottom <= top) bottom = top + 1;
  for (int y = top; y <= bottom && y < H; ++y) {  // a bar taller than a tiny image is cut
    Color c = colormap(s.map, double(bottom - y) / double(bottom - top));
    for (int x = bx; x < bx + bar_w && x < W; ++x)
      for (int k = 0; k < 3; ++k) h.image.at(x, y, k) = c[k];
  }
  TextStyle ts{tick_size, s.text, Align::left};
  int tx = bx + bar_w + 4;
  draw_text(h.image, tx, top - line_h / 2, ticks[0], ts);
  draw_text(h.image, tx, (top + bottom) / 2 - line_h / 2, ticks[1], ts);
  draw_text(h.image, tx, bottom - line_h / 2, ticks[2], ts);
  if (label_h) draw_text(h.image, bx, 0, s.label, ts);
  return h;
}

}  // namespace sn::io

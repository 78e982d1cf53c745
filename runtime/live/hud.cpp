#include "live/hud.h"

#include <algorithm>
#include <cstdio>

#include "gl/overlay.h"
#include "io/overlay.h"
#include "io/text.h"
#include "live/error_report.h"

namespace sn::live {

float overlay_font_size(int w) { return std::clamp(w / 55.f, 10.f, 16.f); }

void Hud::set_error(const std::string& message) {
  error_lines_ = message.empty() ? std::vector<std::string>{} : report_lines(report_error(message));
}

namespace {

// The heatmap's colour bar for the side view's fourth panel: inferno from 0 to `scale`.
io::Image colour_bar(int w, int h, double scale, float size) {
  io::OverlayStyle style;
  style.size = size;
  io::Image img = io::text_box({{"|error|: 0 (black) to " + io::number_text(scale) + " (yellow) or more"}}, w, style);
  int bar_h = std::max(4, h / 6), y0 = img.height;
  io::Image out(w, img.height + bar_h, 4);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 4; ++c) out.at(x, y, c) = img.at(x, y, c);
  for (int y = 0; y < bar_h; ++y)
    for (int x = 0; x < w; ++x) {
      io::Color col = io::colormap(io::Colormap::inferno, w > 1 ? double(x) / (w - 1) : 0);
      for (int c = 0; c < 3; ++c) out.at(x, y0 + y, c) = col[c];
      out.at(x, y0 + y, 3) = 1;
    }
  return out;
}

// A cross-hair on the probed pixel: white arms with a black edge, the pixel itself left clear.
io::Image cross_hair(int arm) {
  int n = 2 * arm + 3;
  io::Image img(n, n, 4);
  for (int d = 2; d <= arm + 1; ++d)
    for (int s : {-1, 1})
      for (int across = -1; across <= 1; ++across) {
        float v = across == 0 ? 1.f : 0.f;
        int c = arm + 1;
        for (auto [x, y] : {std::pair{c + s * d, c + across}, std::pair{c + across, c + s * d}}) {
          for (int k = 0; k < 3; ++k) img.at(x, y, k) = v;
          img.at(x, y, 3) = 1;
        }
      }
  return img;
}

}  // namespace

std::vector<Placed> Hud::layout(int w, int h, const Picture& picture) const {
  std::vector<Placed> out;
  io::OverlayStyle small;
  small.size = overlay_font_size(w);
  small.opacity = 0.6f;
  if (mode_ == "side") {  // 2 x 2 panels of the picture: truth | network, error | legend
    const int x = picture.x, y = picture.y, pw = picture.w / 2, ph = picture.h / 2;
    out.push_back({io::text_box({{"truth"}}, 0, small), x, y});
    out.push_back({io::text_box({{"network"}}, 0, small), x + pw, y});
    out.push_back({io::text_box({{"|error|, scale " + io::number_text(error_scale_)}}, 0, small), x, y + ph});
    out.push_back({colour_bar(std::max(8, pw - 16), ph, error_scale_, small.size), x + pw + 8, y + ph + 8});
  }
  if (!binds_.empty()) {  // under the error box, if any: the error matters more
    io::OverlayStyle style = small;
    style.opacity = 0.7f;
    std::vector<io::OverlayLine> lines;
    for (const auto& l : binds_) lines.push_back({l, {0.75f, 0.95f, 1.f}});
    io::Image box = io::text_box(lines, 0, style);
    if (box.width > w) box = io::text_box(lines, w, style);
    int y = std::max(0, h - box.height);
    out.push_back({std::move(box), 0, y});
  }
  if (!error_lines_.empty()) {
    io::OverlayStyle style;
    style.size = overlay_font_size(w);
    style.background = {0.25f, 0.02f, 0.02f};
    style.opacity = 0.85f;
    std::vector<io::OverlayLine> lines;
    for (size_t i = 0; i < error_lines_.size(); ++i)
      lines.push_back({(i == 0 ? "ERROR " : "") + error_lines_[i],
                       i == 0 ? io::Color{1.f, 0.45f, 0.4f} : i == 1 ? io::Color{1, 1, 1} : io::Color{0.8f, 0.8f, 0.8f}});
    Placed p{io::text_box(lines, w, style), 0, 0};
    p.y = std::max(0, h - p.image.height);
    out.push_back(std::move(p));
  }
  if (!progress_text_.empty()) {
    io::OverlayStyle style;
    style.size = overlay_font_size(w);
    out.push_back({io::progress_bar(progress_, progress_text_, w, {0.15f, 0.45f, 0.85f}, style), 0, 0});
  }
  int top = progress_text_.empty() ? 0 : out.back().image.height;
  if (counter_ && frame_ms_ > 0) {
    char text[64];
    snprintf(text, sizeof text, "%.1f ms  %.1f fps", frame_ms_, 1000 / frame_ms_);
    io::Image box = io::text_box({{text}}, 0, small);
    int x = std::max(0, w - box.width);
    out.push_back({std::move(box), x, top});  // under the progress bar, if any
  }
  if (!probe_lines_.empty()) {
    // The probed frame pixel's centre where it is shown.
    const int px = picture.x + int((probe_x_ + 0.5) * picture.scale), py = picture.y + int((probe_y_ + 0.5) * picture.scale);
    int arm = 5;
    out.push_back({cross_hair(arm), px - arm - 1, py - arm - 1});
    io::OverlayStyle style = small;
    style.opacity = 0.8f;
    std::vector<io::OverlayLine> lines;
    for (const auto& l : probe_lines_) lines.push_back({l});
    io::Image box = io::text_box(lines, 0, style);
    // Below and right of the pixel; flipped to the other side where the picture ends.
    int x = px + 12, y = py + 12;
    if (x + box.width > w) x = std::max(0, px - 12 - box.width);
    if (y + box.height > h) y = std::max(0, py - 12 - box.height);
    out.push_back({std::move(box), x, y});
  }
  if (!notice_.empty()) {
    io::OverlayStyle style;
    style.size = overlay_font_size(w) * 1.2f;
    style.background = {0.3f, 0.2f, 0.02f};
    style.opacity = 0.9f;
    std::vector<io::OverlayLine> lines;
    for (const auto& l : notice_) lines.push_back({l, {1, 0.9f, 0.5f}});
    io::Image box = io::text_box(lines, 0, style);
    if (box.width > w) box = io::text_box(lines, w, style);  // cut to the window rather than run off it
    int x = std::max(0, (w - box.width) / 2), y = std::max(0, (h - box.height) / 2);
    out.push_back({std::move(box), x, y});
  }

  return out;
}

const gl::RenderTarget& Hud::compose(const gl::RenderTarget* frame, int w, int h) {
  if (frame && (w < 1 || h < 1)) w = frame->width(), h = frame->height();
  Picture picture{0, 0, w, h, 1};
  if (frame) {  // fitted inside, the aspect kept (as the window shows a frame without overlays)
    picture.scale = std::min(double(w) / frame->width(), double(h) / frame->height());
    picture.w = int(frame->width() * picture.scale), picture.h = int(frame->height() * picture.scale);
    picture.x = (w - picture.w) / 2, picture.y = (h - picture.h) / 2;
  }
  std::vector<Placed> overlays = layout(w, h, picture);
  if (frame && overlays.empty()) return *frame;
  if (!shown_ || shown_->width() != w || shown_->height() != h) shown_ = std::make_unique<gl::RenderTarget>(w, h);
  if (!frame || picture.w != w || picture.h != h) shown_->clear({0.1f, 0.1f, 0.1f, 1});
  if (frame) gl::copy_color(*frame, *shown_, picture.x, picture.y, picture.w, picture.h);
  for (const Placed& p : overlays) gl::blend_over(*shown_, p.image, p.x, p.y);
  return *shown_;
}

}  // namespace sn::live

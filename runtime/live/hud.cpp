#include "live/hud.h"

#include <algorithm>

#include "gl/overlay.h"
#include "io/overlay.h"
#include "live/error_report.h"

namespace sn::live {

float overlay_font_size(int w) { return std::clamp(w / 55.f, 10.f, 16.f); }

void Hud::set_error(const std::string& message) {
  error_lines_ = message.empty() ? std::vector<std::string>{} : report_lines(report_error(message));
}

std::vector<Placed> Hud::layout(int w, int h) const {
  std::vector<Placed> out;
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
  return out;
}

const gl::RenderTarget& Hud::compose(const gl::RenderTarget* frame, int w, int h) {
  if (frame) w = frame->width(), h = frame->height();
  std::vector<Placed> overlays = layout(w, h);
  if (frame && overlays.empty()) return *frame;
  if (!shown_ || shown_->width() != w || shown_->height() != h) shown_ = std::make_unique<gl::RenderTarget>(w, h);
  if (frame) gl::copy_color(*frame, *shown_);
  else shown_->clear({0.1f, 0.1f, 0.1f, 1});
  for (const Placed& p : overlays) gl::blend_over(*shown_, p.image, p.x, p.y);
  return *shown_;
}

}  // namespace sn::live

// What live mode draws over its view (the heads-up display): the error overlay, the training
// progress bar, the frame-time counter, the panels' labels, the pixel probe and notices. It keeps the last good picture
// untouched: the overlays go on a copy, which the window shows (and SHADENET_LIVE_SHOWN saves).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "gl/render_target.h"
#include "io/image.h"

namespace sn::live {

struct Placed {
  io::Image image;  // RGBA
  int x = 0, y = 0;  // top-left, in the picture's pixels
};

class Hud {
 public:
  // The error to show ("" = none): its report's lines over the bottom of the picture.
  void set_error(const std::string& message);
  bool has_error() const { return !error_lines_.empty(); }
  // Long work under way: a bar across the top, `fraction` (0..1) filled, `text` on it. "" = none.
  void set_progress(const std::string& text, double fraction) { progress_text_ = text, progress_ = fraction; }
  bool has_progress() const { return !progress_text_.empty(); }

  // The view under the overlays: its mode ("side" gets its panels labelled), the heatmap's
  // scale, and the last frame's time in ms (shown as a counter when `counter`; <= 0: none yet).
  void set_view(const std::string& mode, double error_scale, double frame_ms, bool counter) {
    mode_ = mode, error_scale_ = error_scale, frame_ms_ = frame_ms, counter_ = counter;
  }

  // The pixel probe: `lines` (truth, network, error) in a box beside pixel (x, y) of the picture
  // (0-based), with a cross-hair on the pixel; no lines = none.
  void set_probe(std::vector<std::string> lines, int x, int y) { probe_lines_ = std::move(lines), probe_x_ = x, probe_y_ = y; }
  bool has_probe() const { return !probe_lines_.empty(); }

  // The keys bound to values (sn.live.bind), one line each, in the bottom-left corner.
  void set_binds(std::vector<std::string> lines) { binds_ = std::move(lines); }
  const std::vector<std::string>& binds() const { return binds_; }

  // A note for a few seconds (a question such as "press Q again to quit"), centred; {} = none.
  void set_notice(std::vector<std::string> lines) { notice_ = std::move(lines); }
  bool has_notice() const { return !notice_.empty(); }

  // Where the frame lies in what is shown, and how many shown pixels a frame pixel spans.
  struct Picture {
    int x = 0, y = 0, w = 0, h = 0;
    double scale = 1;
  };
  // The overlays for a w x h picture with the frame shown in `picture` of it, in drawing order.
  std::vector<Placed> layout(int w, int h, const Picture& picture) const;

  // The picture to show, w x h (the window's framebuffer; 0 x 0: the frame's size): `frame`
  // fitted inside, letterboxed (may be null: nothing drawn yet, a dark picture), with the
  // overlays blended over it at the shown size, so that a small render size (sn.live.show{ size
  // = ... }) does not magnify them past the window's edges. Returns the target to present (frame
  // itself when no overlay).
  const gl::RenderTarget& compose(const gl::RenderTarget* frame, int w, int h);

 private:
  std::vector<std::string> error_lines_;
  std::string progress_text_;
  double progress_ = 0;
  std::string mode_;
  double error_scale_ = 0.25, frame_ms_ = 0;
  bool counter_ = false;
  std::vector<std::string> probe_lines_;
  int probe_x_ = 0, probe_y_ = 0;
  std::vector<std::string> notice_, binds_;
  std::unique_ptr<gl::RenderTarget> shown_;
};

// The font size for overlays on a picture `w` pixels wide.
float overlay_font_size(int w);

}  // namespace sn::live

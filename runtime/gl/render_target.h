// An offscreen framebuffer: one or more RGBA32F colour attachments and a 32-bit float depth.
// Every render draws here, headless or windowed; a window only presents attachment 0.
#pragma once
#include <array>
#include <memory>

#include "io/image.h"

namespace sn::gl {

class RenderTarget {
 public:
  RenderTarget(int width, int height, int color_attachments = 1);
  ~RenderTarget();
  RenderTarget(const RenderTarget&) = delete;
  RenderTarget& operator=(const RenderTarget&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  int attachments() const { return n_; }
  unsigned fbo() const { return fbo_; }
  unsigned color_texture(int i) const { return color_[i]; }

  // Binds for drawing: viewport, depth test on.
  void bind();
  // Clears every colour attachment to `rgba` and depth to 1.
  void clear(std::array<float, 4> rgba = {0, 0, 0, 0});
  // What may hold something other than the clear state (colour 0, depth 1), in pixels [x0, x1) x
  // [y0, y1) with row 0 at the bottom: the whole target when new, after bind() (any draw) and
  // after mark_drawn() (writers that bypass bind: uploads, image stores); nothing after a clear
  // to (0, 0, 0, 0).
  // A writer that knows it drew only inside a box says so with set_drawn(box) afterwards, and
  // clear_drawn() then clears only that: a per-frame G-buffer or an upload of the pixels around
  // a mesh stops paying for clearing the whole frame (llvmpipe clears RGBA32F a pixel at a time).
  void mark_drawn();
  void set_drawn(std::array<int, 4> box);
  // Clears (colour 0, depth 1) what may have been drawn, except `keep` (about to be overwritten
  // whole by the caller); afterwards nothing counts as drawn.
  void clear_drawn(std::array<int, 4> keep = {0, 0, 0, 0});

  // Reads attachment `i` as a 4-channel float image, top row first.
  io::Image read(int i = 0) const;
  // One pixel of attachment `i` (x, y from the top-left, 0-based): a probe reads 16 bytes, not
  // the whole picture.
  std::array<float, 4> pixel(int x, int y, int i = 0) const;

  static constexpr int kMaxAttachments = 8;

 private:
  void release();
  int width_, height_, n_;
  unsigned fbo_ = 0, depth_ = 0;
  unsigned color_[kMaxAttachments] = {};
  std::array<int, 4> drawn_;
};

// A target of that size that nobody else holds, reused from earlier calls when one is idle (no
// other shared_ptr to it): per-frame G-buffers then cost no allocation (on llvmpipe a new
// 960x720 target with two attachments costs ~10 ms of page faults and zeroing). At most two idle
// targets are kept. Contents are whatever was drawn last: clear before use.
std::shared_ptr<RenderTarget> pooled_target(int width, int height, int color_attachments);
// Frees the idle targets (destroy_current calls it: GL objects die before their context).
void clear_target_pool();

}  // namespace sn::gl

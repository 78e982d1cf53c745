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
  // Reads attachment `i` as a 4-channel float image, top row first.
  io::Image read(int i = 0) const;

  static constexpr int kMaxAttachments = 8;

 private:
  void release();
  int width_, height_, n_;
  unsigned fbo_ = 0, depth_ = 0;
  unsigned color_[kMaxAttachments] = {};
};

// A target of that size that nobody else holds, reused from earlier calls when one is idle (no
// other shared_ptr to it): per-frame G-buffers then cost no allocation (on llvmpipe a new
// 960x720 target with two attachments costs ~10 ms of page faults and zeroing). At most two idle
// targets are kept. Contents are whatever was drawn last: clear before use.
std::shared_ptr<RenderTarget> pooled_target(int width, int height, int color_attachments);
// Frees the idle targets (destroy_current calls it: GL objects die before their context).
void clear_target_pool();

}  // namespace sn::gl

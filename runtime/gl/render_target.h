// An offscreen framebuffer: one or more RGBA32F colour attachments and a 32-bit float depth.
// Every render draws here, headless or windowed; a window only presents attachment 0.
#pragma once
#include <array>

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
  // One pixel of attachment `i` (x, y from the top-left, 0-based): a probe reads 16 bytes, not
  // the whole picture.
  std::array<float, 4> pixel(int x, int y, int i = 0) const;

  static constexpr int kMaxAttachments = 8;

 private:
  void release();
  int width_, height_, n_;
  unsigned fbo_ = 0, depth_ = 0;
  unsigned color_[kMaxAttachments] = {};
};

}  // namespace sn::gl

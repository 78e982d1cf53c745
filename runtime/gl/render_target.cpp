#include "gl/render_target.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "gl/context.h"
#include "gl/pool.h"
#include "io/memory.h"

namespace sn::gl {

RenderTarget::RenderTarget(int width, int height, int n)
    : width_(width), height_(height), n_(n), drawn_{0, 0, width, height} {
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
  if (width < 1 || height < 1 || width > max_size || height > max_size)
    throw std::invalid_argument("render target size " + std::to_string(width) + "x" + std::to_string(height) +
                                " is outside 1.." + std::to_string(max_size));
  if (n < 1 || n > kMaxAttachments)
    throw std::invalid_argument("render target colour attachments must be 1.." + std::to_string(kMaxAttachments));
  // A software driver keeps the target in host memory (16 bytes a pixel per attachment, 4 of depth).
  if (current().info().software)
    io::check_memory(std::uint64_t(width) * std::uint64_t(height) * (16u * unsigned(n) + 4u),
                     "a " + std::to_string(width) + "x" + std::to_string(height) + " render target with " +
                         std::to_string(n) + " attachment(s)");
  check_gl_errors_before("creating a render target");
  glCreateFramebuffers(1, &fbo_);
  glCreateTextures(GL_TEXTURE_2D, n, color_);
  GLenum bufs[kMaxAttachments];
  for (int i = 0; i < n; ++i) {
    glTextureStorage2D(color_[i], 1, GL_RGBA32F, width, height);
    glTextureParameteri(color_[i], GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(color_[i], GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glNamedFramebufferTexture(fbo_, GL_COLOR_ATTACHMENT0 + i, color_[i], 0);
    bufs[i] = GL_COLOR_ATTACHMENT0 + i;
  }
  glNamedFramebufferDrawBuffers(fbo_, n, bufs);
  glCreateRenderbuffers(1, &depth_);
  glNamedRenderbufferStorage(depth_, GL_DEPTH_COMPONENT32F, width, height);
  glNamedFramebufferRenderbuffer(fbo_, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
  if (GLenum e = take_gl_errors(); e != GL_NO_ERROR) {
    release();
    throw std::runtime_error(e == GL_OUT_OF_MEMORY
                                 ? std::string("out of ") + device_memory_name() + " for a " + std::to_string(width) + "x" + std::to_string(height) +
                                       " render target with " + std::to_string(n) + " attachment(s)"
                                 : "cannot make a " + std::to_string(width) + "x" + std::to_string(height) +
                                       " render target: " + gl_error_text(e));
  }
  GLenum status = glCheckNamedFramebufferStatus(fbo_, GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    release();
    throw std::runtime_error("render target incomplete (status 0x" + std::to_string(status) + ")");
  }
}

RenderTarget::~RenderTarget() { release(); }

void RenderTarget::release() {
  if (fbo_) glDeleteFramebuffers(1, &fbo_);
  glDeleteTextures(n_, color_);
  if (depth_) glDeleteRenderbuffers(1, &depth_);
  fbo_ = depth_ = 0;
  for (unsigned& c : color_) c = 0;
}

void RenderTarget::bind() {
  mark_drawn();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glViewport(0, 0, width_, height_);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
}

void RenderTarget::clear(std::array<float, 4> rgba) {
  for (int i = 0; i < n_; ++i) glClearNamedFramebufferfv(fbo_, GL_COLOR, i, rgba.data());
  float one = 1.f;
  glClearNamedFramebufferfv(fbo_, GL_DEPTH, 0, &one);
  const bool blank = rgba == std::array<float, 4>{0, 0, 0, 0};
  drawn_ = blank ? std::array<int, 4>{0, 0, 0, 0} : std::array<int, 4>{0, 0, width_, height_};
}

void RenderTarget::mark_drawn() { drawn_ = {0, 0, width_, height_}; }

void RenderTarget::set_drawn(std::array<int, 4> box) { drawn_ = box; }

void RenderTarget::clear_drawn(std::array<int, 4> keep) {
  const auto [x0, y0, x1, y1] = drawn_;
  drawn_ = {0, 0, 0, 0};
  if (x1 <= x0 || y1 <= y0) return;
  auto [kx0, ky0, kx1, ky1] = keep;
  if (kx1 <= kx0 || ky1 <= ky0) kx0 = kx1 = ky0 = ky1 = 0;
  // The drawn rectangle less `keep`: the strips below and above it, and left and right of it.
  const int mid0 = std::max(y0, std::min(y1, ky0)), mid1 = std::min(y1, std::max(mid0, ky1));
  const std::array<std::array<int, 4>, 4> parts = {{{x0, y0, x1, mid0},
                                                    {x0, mid1, x1, y1},
                                                    {x0, mid0, std::min(x1, std::max(x0, kx0)), mid1},
                                                    {std::max(x0, std::min(x1, kx1)), mid0, x1, mid1}}};
  const float zero[4] = {0, 0, 0, 0}, one = 1.f;
  glEnable(GL_SCISSOR_TEST);
  for (const auto& [a0, b0, a1, b1] : parts) {
    if (a1 <= a0 || b1 <= b0) continue;
    glScissor(a0, b0, a1 - a0, b1 - b0);
    for (int i = 0; i < n_; ++i) glClearNamedFramebufferfv(fbo_, GL_COLOR, i, zero);
    glClearNamedFramebufferfv(fbo_, GL_DEPTH, 0, &one);
  }
  glDisable(GL_SCISSOR_TEST);
}

std::array<float, 4> RenderTarget::pixel(int x, int y, int i) const {
  if (i < 0 || i >= n_)
    throw std::out_of_range("render target has attachments 1.." + std::to_string(n_) + ", asked for " +
                            std::to_string(i + 1));
  if (x < 0 || x >= width_ || y < 0 || y >= height_)
    throw std::out_of_range("pixel (" + std::to_string(x + 1) + ", " + std::to_string(y + 1) + ") is outside the " +
                            std::to_string(width_) + "x" + std::to_string(height_) + " target (1.." +
                            std::to_string(width_) + ", 1.." + std::to_string(height_) + ")");
  glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  std::array<float, 4> p{};
  glGetTextureSubImage(color_[i], 0, x, height_ - 1 - y, 0, 1, 1, 1, GL_RGBA, GL_FLOAT, sizeof p, p.data());
  return p;
}

io::Image RenderTarget::read(int i) const {
  if (i < 0 || i >= n_)
    throw std::out_of_range("render target has attachments 1.." + std::to_string(n_) + ", asked for " +
                            std::to_string(i + 1));
  glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  io::Image img(width_, height_, 4);
  glGetTextureImage(color_[i], 0, GL_RGBA, GL_FLOAT, GLsizei(img.pixels.size() * 4), img.pixels.data());
  // GL's first row is the bottom one; images run top to bottom.
  const size_t row = size_t(width_) * 4;
  for (int y = 0; y < height_ / 2; ++y)
    std::swap_ranges(img.pixels.begin() + y * row, img.pixels.begin() + (y + 1) * row,
                     img.pixels.begin() + (height_ - 1 - y) * row);
  return img;
}

namespace {
Pool<RenderTarget>& pool() {
  static Pool<RenderTarget> p(2);
  return p;
}
}  // namespace

std::shared_ptr<RenderTarget> pooled_target(int width, int height, int n) {
  // A large target is not kept idle: two of a 4096x4096 render held 1 GB for the rest of the
  // process. Up to 128 MiB of colour (1920x1080 with 3 attachments) is pooled, as frames and
  // dataset views need.
  constexpr double kPooledBytes = 128.0 * 1024 * 1024;
  if (double(width) * double(height) * double(n) * 16.0 > kPooledBytes)
    return std::make_shared<RenderTarget>(width, height, n);
  return pool().take(
      [&](const RenderTarget& t) { return t.width() == width && t.height() == height && t.attachments() == n; },
      [](const RenderTarget&, const RenderTarget&) { return false; },  // the first that fits
      [&] { return std::make_shared<RenderTarget>(width, height, n); });
}

void clear_target_pool() { pool().clear(); }

}  // namespace sn::gl

// The OpenGL 4.5 core context every GL object lives in: headless through EGL (default)
// or a GLFW window. Both render offscreen; a window only presents the result.
#pragma once
#include <memory>
#include <string>
#include <utility>

#include "io/image.h"

namespace sn::gl {

struct ContextInfo {
  std::string vendor, renderer, version;
  bool software = false;  // llvmpipe, softpipe, swrast: no hardware GPU
  int max_shared_memory = 0;  // GL_MAX_COMPUTE_SHARED_MEMORY_SIZE, bytes
};

class Context {
 public:
  // EGL surfaceless (Mesa) or EGL device (NVIDIA) context; throws with a reason on failure.
  static std::unique_ptr<Context> headless();
  // A visible GLFW window of the given size; throws when no display can be opened.
  static std::unique_ptr<Context> window(int width, int height, const std::string& title);

  virtual ~Context() = default;
  const ContextInfo& info() const { return info_; }
  virtual bool windowed() const { return false; }
  // Shows the colour attachment 0 of framebuffer `fbo` (size w x h) in the window, scaled to fit.
  // With `capture`, also reads back what the window shows (its whole framebuffer, RGBA).
  virtual void present(unsigned fbo, int w, int h, io::Image* capture = nullptr) {
    (void)fbo, (void)w, (void)h, (void)capture;
  }
  virtual void set_title(const std::string&) {}
  virtual std::pair<int, int> framebuffer_size() const { return {0, 0}; }
  virtual bool should_close() const { return false; }
  // Processes window events; waits up to `timeout_s` for one when > 0 (an idle window sleeps).
  virtual void poll(double timeout_s = 0) { (void)timeout_s; }
  virtual void* native_window() { return nullptr; }

 protected:
  void query_info();  // fills info_ once the context is current
  ContextInfo info_;
};

// The process-wide context, created on first use (headless unless `open_window` ran first).
Context& current();
bool has_current();
void set_current(std::unique_ptr<Context> ctx);
void destroy_current();

// Reads and clears every pending GL error flag; returns the first (0 = none). Allocations call
// it before and after, so a failure earlier (say, a render target too large) is not blamed on
// the next small buffer.
unsigned take_gl_errors();

}  // namespace sn::gl

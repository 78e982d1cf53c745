// The OpenGL 4.5 core context every GL object lives in: headless through EGL (default)
// or a GLFW window. Both render offscreen; a window only presents the result.
#pragma once
#include <memory>
#include <string>
#include <utility>

#include "io/image.h"

namespace sn::gl {

// What the context runs on and the limits shadenet's kernels are sized by; `shadenet --gl-info`
// prints it (info_text) and sn.gl_info() returns it.
struct ContextInfo {
  std::string vendor, renderer, version, glsl_version;  // GL_VENDOR, GL_RENDERER, GL_VERSION, GLSL
  bool software = false;  // llvmpipe, softpipe, swrast: no hardware GPU
  // How the context was made: "device" or "surfaceless" (EGL, gl/egl_context.cpp) or "window" (GLFW).
  std::string platform;
  std::string egl_vendor, egl_version;  // of the EGL display ("" in a window)
  std::string egl_device_extensions;    // of the EGL device ("" on the surfaceless platform)
  std::string egl_device_file;          // its DRM device file or render node, when it has one
  std::string egl_devices;              // "none (why)" when EGL named no device, else ""
  int max_shared_memory = 0;            // GL_MAX_COMPUTE_SHARED_MEMORY_SIZE, bytes
  int max_workgroup_size[3] = {0, 0, 0};  // GL_MAX_COMPUTE_WORK_GROUP_SIZE
  int max_workgroup_invocations = 0;      // GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS
  long long max_ssbo_size = 0;            // GL_MAX_SHADER_STORAGE_BLOCK_SIZE, bytes
  int max_uniform_block_size = 0;         // GL_MAX_UNIFORM_BLOCK_SIZE, bytes
};

// SHADENET_GL_DEBUG's setting: "" (off, or unset), "1" or "all"; throws on any other value.
std::string debug_output_choice();

// ContextInfo as "name: value" lines, the output of `shadenet --gl-info`.
std::string info_text(const ContextInfo& info);

class Context {
 public:
  // EGL device (a GPU's driver first) or surfaceless (Mesa) context, SHADENET_EGL_PLATFORM=
  // auto|device|surfaceless picks (gl/egl_context.cpp); throws with a reason on failure.
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
  void query_info();  // fills info_ once the context is current, then enable_debug_output()
  // SHADENET_GL_DEBUG=1 prints the driver's debug messages (errors, warnings, performance) to
  // stderr as they happen; =all adds its notifications (where a driver places each buffer).
  void enable_debug_output();
  ContextInfo info_;
};

// The process-wide context, created on first use (headless unless `open_window` ran first).
Context& current();
bool has_current();
void set_current(std::unique_ptr<Context> ctx);
void destroy_current();
// "GPU memory", or on a software driver (llvmpipe) "memory (the software GL driver's: host memory)",
// for out-of-memory errors.
const char* device_memory_name();

// Reads and clears every pending GL error flag; returns the first (0 = none).
unsigned take_gl_errors();
// Throws "a GL call before WHAT failed: GL_..." when an error is pending. Dispatches and
// allocations call it first: an earlier call's error is then neither dropped with its wrong
// result nor blamed on them.
void check_gl_errors_before(const std::string& what);
// "0x502": a GL or EGL error code as the specifications print it.
std::string hex_code(unsigned code);
// "GL_INVALID_OPERATION (0x502)", or the code alone for one that is not a standard error.
std::string gl_error_text(unsigned error);

}  // namespace sn::gl

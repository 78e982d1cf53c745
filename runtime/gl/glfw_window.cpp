// Windowed context: a GLFW window whose default framebuffer only shows what was rendered
// offscreen, so a window and a headless run draw the very same pixels.
#include <epoxy/gl.h>
#include <GLFW/glfw3.h>

#include <algorithm>
#include <stdexcept>
#include <string>

#include "gl/context.h"

namespace sn::gl {

namespace {

std::string g_glfw_error;
void on_glfw_error(int, const char* message) { g_glfw_error = message; }

class GlfwWindow final : public Context {
 public:
  GlfwWindow(int width, int height, const std::string& title) {
    glfwSetErrorCallback(on_glfw_error);
    if (!glfwInit())
      throw std::runtime_error("--window: could not open a display (" + g_glfw_error +
                               "); set DISPLAY or run under xvfb-run");
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, debug_output_choice().empty() ? GLFW_FALSE : GLFW_TRUE);
    window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!window_) {
      glfwTerminate();
      throw std::runtime_error("--window: could not create an OpenGL 4.5 core window (" + g_glfw_error + ")");
    }
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(1);
    info_.platform = "window";
    query_info();
  }
  ~GlfwWindow() override {
    glfwDestroyWindow(window_);
    glfwTerminate();
  }
  bool windowed() const override { return true; }
  void present(unsigned fbo, int w, int h, io::Image* capture) override {
    int fw = 0, fh = 0;
    glfwGetFramebufferSize(window_, &fw, &fh);
    // Keep the aspect ratio: letterbox the image inside the window.
    double s = std::min(double(fw) / w, double(fh) / h);
    int dw = int(w * s), dh = int(h * s), x0 = (fw - dw) / 2, y0 = (fh - dh) / 2;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, fw, fh);
    glClearColor(0.1f, 0.1f, 0.1f, 1.f);
    glClear(GL_COLOR_BUFFER_BIT);
    glBlitNamedFramebuffer(fbo, 0, 0, 0, w, h, x0, y0, x0 + dw, y0 + dh, GL_COLOR_BUFFER_BIT,
                           dw == w && dh == h ? GL_NEAREST : GL_LINEAR);
    if (capture) {  // read the back buffer before the swap leaves it undefined
      *capture = io::Image(fw, fh, 4);
      glReadBuffer(GL_BACK);
      glPixelStorei(GL_PACK_ALIGNMENT, 1);
      glReadPixels(0, 0, fw, fh, GL_RGBA, GL_FLOAT, capture->pixels.data());
      const size_t row = size_t(fw) * 4;
      for (int y = 0; y < fh / 2; ++y)
        std::swap_ranges(capture->pixels.begin() + y * row, capture->pixels.begin() + (y + 1) * row,
                         capture->pixels.begin() + (fh - 1 - y) * row);
    }
    glfwSwapBuffers(window_);
  }
  void set_title(const std::string& title) override { glfwSetWindowTitle(window_, title.c_str()); }
  std::pair<int, int> framebuffer_size() const override {
    int fw = 0, fh = 0;
    glfwGetFramebufferSize(window_, &fw, &fh);
    return {fw, fh};
  }
  bool should_close() const override { return glfwWindowShouldClose(window_); }
  void poll(double timeout_s) override {
    if (timeout_s > 0) glfwWaitEventsTimeout(timeout_s);
    else glfwPollEvents();
  }
  void* native_window() override { return window_; }

 private:
  GLFWwindow* window_ = nullptr;
};

}  // namespace

std::unique_ptr<Context> Context::window(int width, int height, const std::string& title) {
  return std::make_unique<GlfwWindow>(width, height, title);
}

}  // namespace sn::gl

// Headless context: EGL with no surface. Mesa offers EGL_PLATFORM_SURFACELESS_MESA (llvmpipe
// without a GPU); NVIDIA's driver offers EGL_PLATFORM_DEVICE_EXT. Either gives GL 4.5 core.
#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <stdexcept>
#include <string>

#include "gl/context.h"

namespace sn::gl {

namespace {

class EglContext final : public Context {
 public:
  EglContext() {
    if (!epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_platform_base"))
      throw std::runtime_error("EGL: EGL_EXT_platform_base is missing (is libegl-mesa0 installed?)");
    std::string tried;
    if (epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless")) {
      display_ = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
      tried += " surfaceless";
      if (display_ != EGL_NO_DISPLAY && !eglInitialize(display_, nullptr, nullptr)) display_ = EGL_NO_DISPLAY;
    }
    if (display_ == EGL_NO_DISPLAY && epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_platform_device")) {
      EGLDeviceEXT devices[8];
      EGLint count = 0;
      tried += " device";
      if (eglQueryDevicesEXT(8, devices, &count) && count > 0) {
        for (EGLint i = 0; i < count && display_ == EGL_NO_DISPLAY; ++i) {
          display_ = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
          if (display_ != EGL_NO_DISPLAY && !eglInitialize(display_, nullptr, nullptr)) display_ = EGL_NO_DISPLAY;
        }
      }
    }
    if (display_ == EGL_NO_DISPLAY)
      throw std::runtime_error("EGL: no display could be initialised (tried:" + tried +
                               "); install libegl-mesa0 and libgl1-mesa-dri");
    if (!eglBindAPI(EGL_OPENGL_API)) throw std::runtime_error("EGL: OpenGL API not available");

    EGLConfig config = nullptr;
    if (!epoxy_has_egl_extension(display_, "EGL_KHR_no_config_context")) {
      const EGLint attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
      EGLint n = 0;
      if (!eglChooseConfig(display_, attribs, &config, 1, &n) || n == 0)
        throw std::runtime_error("EGL: no OpenGL config");
    }
    const EGLint ctx_attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                  EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                  EGL_NONE};
    context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, ctx_attribs);
    if (context_ == EGL_NO_CONTEXT)
      throw std::runtime_error("EGL: could not create an OpenGL 4.5 core context (error 0x" +
                               hex(eglGetError()) + ")");
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
      throw std::runtime_error("EGL: eglMakeCurrent failed");
    query_info();
  }
  ~EglContext() override {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
    eglTerminate(display_);
  }

 private:
  static std::string hex(EGLint v) {
    char buf[16];
    snprintf(buf, sizeof buf, "%x", v);
    return buf;
  }
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<Context> Context::headless() { return std::make_unique<EglContext>(); }

}  // namespace sn::gl

// Headless context: EGL with no surface, on one of two platforms (SHADENET_EGL_PLATFORM):
//   auto (default)  a hardware EGL device first (NVIDIA's driver; Mesa on a GPU), then Mesa's
//                   surfaceless platform, then a software EGL device. Surfaceless first would
//                   take llvmpipe on a GPU machine whenever glvnd loads Mesa beside the driver.
//   device          EGL devices only, hardware first: on a machine without a GPU this is Mesa's
//                   software device (EGL_MESA_device_software), which runs the device path on
//                   llvmpipe so that the tests exercise it.
//   surfaceless     Mesa's surfaceless platform only.
// Each gives GL 4.5 core; ContextInfo says which platform and device were taken.
#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <algorithm>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "gl/context.h"

#ifndef EGL_DRM_RENDER_NODE_FILE_EXT
#define EGL_DRM_RENDER_NODE_FILE_EXT 0x3377  // EGL_EXT_device_drm_render_node; epoxy 1.5 lacks it
#endif

namespace sn::gl {

namespace {

bool has_word(const std::string& list, const std::string& word) {
  std::istringstream in(list);
  std::string w;
  while (in >> w)
    if (w == word) return true;
  return false;
}

std::string device_string(EGLDeviceEXT device, EGLint name) {
  const char* s = eglQueryDeviceStringEXT(device, name);
  return s ? s : "";
}

// One way to a display: an EGL device, or the surfaceless platform (device == nullptr).
struct Candidate {
  EGLDeviceEXT device = nullptr;
  std::string extensions, file;  // the device's extensions and DRM device file ("" when none)
  bool software = false;         // Mesa's software device (llvmpipe)
};

// Every EGL device, hardware ones first (in the driver's order); `why` says why there are none.
std::vector<Candidate> egl_devices(std::string& why) {
  std::vector<Candidate> out;
  // EGL_EXT_device_base is device_enumeration and device_query in one (EGL_EXT_device_base's
  // specification): a driver may name only it.
  if (!epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_platform_device")) {
    why = "the EGL client extensions lack EGL_EXT_platform_device";
    return out;
  }
  if (!epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_device_enumeration") &&
      !epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_device_base")) {
    why = "the EGL client extensions lack EGL_EXT_device_enumeration";
    return out;
  }
  EGLDeviceEXT devices[16];
  EGLint count = 0;
  if (!eglQueryDevicesEXT(16, devices, &count)) {
    why = "eglQueryDevicesEXT failed (EGL error " + hex_code(unsigned(eglGetError())) + ")";
    return out;
  }
  if (count == 0) why = "eglQueryDevicesEXT found none";
  for (EGLint i = 0; i < count; ++i) {
    Candidate c;
    c.device = devices[i];
    c.extensions = device_string(devices[i], EGL_EXTENSIONS);
    c.software = has_word(c.extensions, "EGL_MESA_device_software");
    if (has_word(c.extensions, "EGL_EXT_device_drm")) c.file = device_string(devices[i], EGL_DRM_DEVICE_FILE_EXT);
    if (c.file.empty() && has_word(c.extensions, "EGL_EXT_device_drm_render_node"))
      c.file = device_string(devices[i], EGL_DRM_RENDER_NODE_FILE_EXT);
    out.push_back(c);
  }
  std::stable_partition(out.begin(), out.end(), [](const Candidate& c) { return !c.software; });
  return out;
}

// The candidates SHADENET_EGL_PLATFORM allows, in the order they are tried; `why` as egl_devices.
std::vector<Candidate> candidates(const std::string& choice, std::string& why) {
  const bool surfaceless = epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless");
  std::vector<Candidate> devices = egl_devices(why), out;
  if (choice == "device") return devices;
  if (choice == "surfaceless") return surfaceless ? std::vector<Candidate>{Candidate{}} : out;
  for (const auto& d : devices)
    if (!d.software) out.push_back(d);
  if (surfaceless) out.push_back(Candidate{});
  for (const auto& d : devices)
    if (d.software) out.push_back(d);
  return out;
}

std::string platform_choice() {
  const char* env = std::getenv("SHADENET_EGL_PLATFORM");
  std::string choice = env && *env ? env : "auto";
  if (choice != "auto" && choice != "device" && choice != "surfaceless")
    throw std::runtime_error("SHADENET_EGL_PLATFORM='" + choice + "': unknown EGL platform (valid: auto, device, surfaceless)");
  return choice;
}

class EglContext final : public Context {
 public:
  EglContext() {
    if (!epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_platform_base"))
      throw std::runtime_error("EGL: EGL_EXT_platform_base is missing (is libegl-mesa0 installed?)");
    const std::string choice = platform_choice();
    std::string tried, no_device;
    for (const Candidate& c : candidates(choice, no_device)) {
      display_ = c.device ? eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, c.device, nullptr)
                          : eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
      tried += c.device ? (c.software ? " device(software)" : " device(" + (c.file.empty() ? "hardware" : c.file) + ")")
                        : " surfaceless";
      if (display_ != EGL_NO_DISPLAY && eglInitialize(display_, nullptr, nullptr)) {
        info_.platform = c.device ? "device" : "surfaceless";
        info_.egl_device_extensions = c.extensions;
        info_.egl_device_file = c.file;
        break;
      }
      display_ = EGL_NO_DISPLAY;
    }
    if (display_ == EGL_NO_DISPLAY)
      throw std::runtime_error("EGL: no display could be initialised (SHADENET_EGL_PLATFORM=" + choice + ", tried:" +
                               (tried.empty() ? " nothing: no EGL device and no surfaceless platform" : tried) +
                               (no_device.empty() ? "" : "; no EGL device: " + no_device) +
                               "); install libegl-mesa0 and libgl1-mesa-dri, or the GPU's driver");
    info_.egl_devices = no_device.empty() ? "" : "none (" + no_device + ")";
    const char* vendor = eglQueryString(display_, EGL_VENDOR);
    const char* version = eglQueryString(display_, EGL_VERSION);
    info_.egl_vendor = vendor ? vendor : "";
    info_.egl_version = version ? version : "";
    if (!eglBindAPI(EGL_OPENGL_API)) throw std::runtime_error("EGL: OpenGL API not available");

    EGLConfig config = nullptr;
    if (!epoxy_has_egl_extension(display_, "EGL_KHR_no_config_context")) {
      const EGLint attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
      EGLint n = 0;
      if (!eglChooseConfig(display_, attribs, &config, 1, &n) || n == 0)
        throw std::runtime_error("EGL: no OpenGL config");
    }
    std::vector<EGLint> ctx_attribs = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                       EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT};
    if (!debug_output_choice().empty()) ctx_attribs.insert(ctx_attribs.end(), {EGL_CONTEXT_OPENGL_DEBUG, EGL_TRUE});
    ctx_attribs.push_back(EGL_NONE);
    context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, ctx_attribs.data());
    if (context_ == EGL_NO_CONTEXT)
      throw std::runtime_error("EGL: could not create an OpenGL 4.5 core context (error " +
                               hex_code(unsigned(eglGetError())) + ")");
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
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<Context> Context::headless() { return std::make_unique<EglContext>(); }

}  // namespace sn::gl

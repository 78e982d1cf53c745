#include "gl/context.h"

#include "gl/buffer.h"
#include "gl/render_target.h"

#include "gl/program.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace sn::gl {

namespace {
std::unique_ptr<Context> g_context;

std::string gl_string(GLenum name) {
  const GLubyte* s = glGetString(name);
  return s ? reinterpret_cast<const char*>(s) : "";
}

const char* debug_severity(GLenum s) {
  switch (s) {
    case GL_DEBUG_SEVERITY_HIGH: return "high";
    case GL_DEBUG_SEVERITY_MEDIUM: return "medium";
    case GL_DEBUG_SEVERITY_LOW: return "low";
    default: return "notification";
  }
}

// `all` (the callback's user pointer) is non-null when notifications are printed too.
void GLAPIENTRY print_debug_message(GLenum, GLenum type, GLuint id, GLenum severity, GLsizei, const GLchar* message,
                                    const void* all) {
  if (severity == GL_DEBUG_SEVERITY_NOTIFICATION && !all) return;
  std::fprintf(stderr, "GL debug (%s%s, id %u): %s\n", debug_severity(severity),
               type == GL_DEBUG_TYPE_ERROR ? ", error" : "", id, message);
}
}  // namespace

std::string debug_output_choice() {
  const char* env = std::getenv("SHADENET_GL_DEBUG");
  const std::string choice = env ? env : "";
  if (!choice.empty() && choice != "1" && choice != "all" && choice != "0")
    throw std::runtime_error("SHADENET_GL_DEBUG='" + choice + "': unknown setting (valid: 0, 1, all)");
  return choice == "0" ? "" : choice;
}

void Context::enable_debug_output() {
  const std::string choice = debug_output_choice();
  if (choice.empty()) return;
  // Synchronous, so that a message is printed inside the call that caused it.
  glEnable(GL_DEBUG_OUTPUT);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDebugMessageCallback(print_debug_message, choice == "all" ? this : nullptr);
}

void Context::query_info() {
  info_.vendor = gl_string(GL_VENDOR);
  info_.renderer = gl_string(GL_RENDERER);
  info_.version = gl_string(GL_VERSION);
  std::string r = info_.renderer;
  std::transform(r.begin(), r.end(), r.begin(), [](unsigned char c) { return std::tolower(c); });
  info_.software = r.find("llvmpipe") != std::string::npos || r.find("softpipe") != std::string::npos ||
                   r.find("swrast") != std::string::npos;
  info_.glsl_version = gl_string(GL_SHADING_LANGUAGE_VERSION);
  glGetIntegerv(GL_MAX_COMPUTE_SHARED_MEMORY_SIZE, &info_.max_shared_memory);
  for (int i = 0; i < 3; ++i) glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_SIZE, i, &info_.max_workgroup_size[i]);
  glGetIntegerv(GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS, &info_.max_workgroup_invocations);
  GLint64 ssbo = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &ssbo);
  info_.max_ssbo_size = ssbo;
  glGetIntegerv(GL_MAX_UNIFORM_BLOCK_SIZE, &info_.max_uniform_block_size);
  enable_debug_output();
}

std::string info_text(const ContextInfo& i) {
  auto or_none = [](const std::string& s) { return s.empty() ? std::string("(none)") : s; };
  std::string t;
  t += "platform: " + i.platform + (i.platform == "window" ? " (GLFW)" : " (EGL)") + "\n";
  if (i.platform != "window") {
    t += "EGL vendor: " + i.egl_vendor + "\n";
    t += "EGL version: " + i.egl_version + "\n";
    if (!i.egl_devices.empty()) t += "EGL devices: " + i.egl_devices + "\n";
    if (i.platform == "device") {
      t += "EGL device extensions: " + or_none(i.egl_device_extensions) + "\n";
      t += "EGL device file: " + or_none(i.egl_device_file) + "\n";
    }
  }
  t += "GL vendor: " + i.vendor + "\n";
  t += "GL renderer: " + i.renderer + (i.software ? " (software)" : "") + "\n";
  t += "GL version: " + i.version + "\n";
  t += "GLSL version: " + i.glsl_version + "\n";
  t += "max compute workgroup size: " + std::to_string(i.max_workgroup_size[0]) + " x " +
       std::to_string(i.max_workgroup_size[1]) + " x " + std::to_string(i.max_workgroup_size[2]) + "\n";
  t += "max compute workgroup invocations: " + std::to_string(i.max_workgroup_invocations) + "\n";
  t += "max compute shared memory: " + std::to_string(i.max_shared_memory) + " bytes\n";
  t += "max shader storage block: " + std::to_string(i.max_ssbo_size) + " bytes\n";
  t += "max uniform block: " + std::to_string(i.max_uniform_block_size) + " bytes\n";
  return t;
}

Context& current() {
  if (!g_context) g_context = Context::headless();
  return *g_context;
}
bool has_current() { return g_context != nullptr; }
void set_current(std::unique_ptr<Context> ctx) { g_context = std::move(ctx); }
void destroy_current() {
  clear_program_cache();  // GL objects die before the context that owns them
  clear_target_pool();
  clear_buffer_pool();
  g_context.reset();
}

unsigned take_gl_errors() {
  GLenum first = GL_NO_ERROR;
  for (int i = 0; i < 32; ++i) {  // a bounded loop: a lost context can report errors forever
    GLenum e = glGetError();
    if (e == GL_NO_ERROR) break;
    if (first == GL_NO_ERROR) first = e;
  }
  return first;
}

void check_gl_errors_before(const std::string& what) {
  if (GLenum e = take_gl_errors(); e != GL_NO_ERROR)
    throw std::runtime_error("a GL call before " + what + " failed: " + gl_error_text(e) +
                             " (SHADENET_GL_DEBUG=1 prints the driver's reason)");
}

std::string hex_code(unsigned code) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%x", code);
  return buf;
}

std::string gl_error_text(unsigned error) {
  switch (error) {
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM (0x500)";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE (0x501)";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION (0x502)";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY (0x505)";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION (0x506)";
    default: return hex_code(error);
  }
}

const char* device_memory_name() {
  return current().info().software ? "memory (the software GL driver's: host memory)" : "GPU memory";
}

}  // namespace sn::gl

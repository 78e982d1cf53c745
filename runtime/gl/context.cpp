#include "gl/context.h"

#include "gl/buffer.h"
#include "gl/render_target.h"

#include "gl/program.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cctype>

namespace sn::gl {

namespace {
std::unique_ptr<Context> g_context;

std::string gl_string(GLenum name) {
  const GLubyte* s = glGetString(name);
  return s ? reinterpret_cast<const char*>(s) : "";
}
}  // namespace

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
}

std::string info_text(const ContextInfo& i) {
  auto or_none = [](const std::string& s) { return s.empty() ? std::string("(none)") : s; };
  std::string t;
  t += "platform: " + i.platform + (i.platform == "window" ? " (GLFW)" : " (EGL)") + "\n";
  if (i.platform != "window") {
    t += "EGL vendor: " + i.egl_vendor + "\n";
    t += "EGL version: " + i.egl_version + "\n";
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

}  // namespace sn::gl

#include "gl/context.h"

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
  glGetIntegerv(GL_MAX_COMPUTE_SHARED_MEMORY_SIZE, &info_.max_shared_memory);
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

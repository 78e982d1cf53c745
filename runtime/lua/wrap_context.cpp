// sn.gl_info(), sn.finish(), sn.windowed(), sn.present(target), sn.clock(), sn.hash(text).
#include <chrono>

#include "gl/buffer.h"
#include "gl/context.h"
#include "gl/render_target.h"
#include "io/build_id.h"
#include "io/hash.h"
#include "lua/binding.h"
#include "lua/module.h"

namespace sn::lua {

namespace {

// The same ContextInfo that `shadenet --gl-info` prints (gl::info_text).
int w_gl_info(lua_State* L) {
  const auto& i = gl::current().info();
  auto str = [L](const char* k, const std::string& v) { lua_pushstring(L, v.c_str()), lua_setfield(L, -2, k); };
  auto num = [L](const char* k, double v) { lua_pushnumber(L, v), lua_setfield(L, -2, k); };
  lua_createtable(L, 0, 16);
  str("vendor", i.vendor), str("renderer", i.renderer), str("version", i.version), str("glsl_version", i.glsl_version);
  lua_pushboolean(L, i.software), lua_setfield(L, -2, "software");
  str("platform", i.platform), str("egl_vendor", i.egl_vendor), str("egl_version", i.egl_version);
  str("egl_device_extensions", i.egl_device_extensions), str("egl_device_file", i.egl_device_file);
  str("egl_devices", i.egl_devices);
  num("max_shared_memory", i.max_shared_memory);
  lua_createtable(L, 3, 0);
  for (int k = 0; k < 3; ++k) lua_pushinteger(L, i.max_workgroup_size[k]), lua_rawseti(L, -2, k + 1);
  lua_setfield(L, -2, "max_workgroup_size");
  num("max_workgroup_invocations", i.max_workgroup_invocations);
  num("max_ssbo_size", double(i.max_ssbo_size));  // may exceed 2^31 on a GPU: a double holds it exactly
  num("max_uniform_block_size", i.max_uniform_block_size);
  return 1;
}

int w_finish(lua_State*) {
  gl::finish();
  return 0;
}

int w_windowed(lua_State* L) {
  lua_pushboolean(L, gl::has_current() && gl::current().windowed());
  return 1;
}

int w_clock(lua_State* L) {
  using namespace std::chrono;
  static const auto t0 = steady_clock::now();
  lua_pushnumber(L, duration<double>(steady_clock::now() - t0).count());
  return 1;
}

// sn.hash(text) -> 16 hex digits: io::fnv1a of the bytes (not cryptographic), the project's one
// content hash, for keys a script compares (lib.claim's sweep keys).
int w_hash(lua_State* L) {
  if (lua_type(L, 1) != LUA_TSTRING) throw Error("sn.hash: a string expected, got " + type_name_at(L, 1));
  std::size_t n = 0;
  const char* bytes = lua_tolstring(L, 1, &n);
  lua_pushstring(L, io::hex64(io::fnv1a(std::string(bytes, n))).c_str());
  return 1;
}

}  // namespace

void open_context(lua_State* L) {
  static const luaL_Reg fns[] = {
      SN_FN("gl_info", w_gl_info), SN_FN("finish", w_finish), SN_FN("windowed", w_windowed),
      SN_FN("clock", w_clock), SN_FN("hash", w_hash), {nullptr, nullptr}};
  luaL_register(L, nullptr, fns);
  lua_pushstring(L, SHADENET_VERSION);
  lua_setfield(L, -2, "version");
  lua_pushstring(L, io::build_id());
  lua_setfield(L, -2, "build");
}

}  // namespace sn::lua

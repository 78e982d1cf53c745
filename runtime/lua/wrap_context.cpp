// sn.gl_info(), sn.finish(), sn.windowed(), sn.present(target), sn.clock().
#include <chrono>

#include "gl/buffer.h"
#include "gl/context.h"
#include "gl/render_target.h"
#include "lua/binding.h"
#include "lua/module.h"

namespace sn::lua {

namespace {

int w_gl_info(lua_State* L) {
  const auto& i = gl::current().info();
  lua_createtable(L, 0, 5);
  lua_pushstring(L, i.vendor.c_str()), lua_setfield(L, -2, "vendor");
  lua_pushstring(L, i.renderer.c_str()), lua_setfield(L, -2, "renderer");
  lua_pushstring(L, i.version.c_str()), lua_setfield(L, -2, "version");
  lua_pushboolean(L, i.software), lua_setfield(L, -2, "software");
  lua_pushinteger(L, i.max_shared_memory), lua_setfield(L, -2, "max_shared_memory");
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

}  // namespace

void open_context(lua_State* L) {
  static const luaL_Reg fns[] = {
      SN_FN("gl_info", w_gl_info), SN_FN("finish", w_finish), SN_FN("windowed", w_windowed),
      SN_FN("clock", w_clock), {nullptr, nullptr}};
  luaL_register(L, nullptr, fns);
  lua_pushstring(L, SHADENET_VERSION);
  lua_setfield(L, -2, "version");
}

}  // namespace sn::lua

// shadenet [options] script.lua [args...]: runs a Lua experiment script, headless by default;
// --watch keeps it live (runtime/live/live_loop.h).
#include <malloc.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <lua.hpp>

#include "live/live_loop.h"
#include "app/options.h"
#include "gl/context.h"
#include "io/build_id.h"
#include "lua/module.h"

namespace {

int traceback(lua_State* L) {
  const char* msg = lua_tostring(L, 1);
  if (!msg) msg = lua_pushfstring(L, "(error object is a %s value)", luaL_typename(L, 1));
  lua_getglobal(L, "debug");
  lua_getfield(L, -1, "traceback");
  lua_pushstring(L, msg);
  lua_pushinteger(L, 2);
  lua_call(L, 2, 1);
  return 1;
}

// A Lua state with the shadenet module and the global `arg`, as the standalone lua interpreter sets it.
lua_State* new_state(const sn::app::Options& opt) {
  lua_State* L = luaL_newstate();
  if (!L) return nullptr;
  luaL_openlibs(L);
  sn::lua::install(L);
  lua_createtable(L, int(opt.script_args.size()), 2);
  lua_pushstring(L, opt.program.c_str());  // arg[-1]: this executable, for scripts that run shadenet again
  lua_rawseti(L, -2, -1);
  lua_pushstring(L, opt.script.c_str());
  lua_rawseti(L, -2, 0);
  for (size_t i = 0; i < opt.script_args.size(); ++i) {
    lua_pushstring(L, opt.script_args[i].c_str());
    lua_rawseti(L, -2, int(i + 1));
  }
  lua_setglobal(L, "arg");
  return L;
}

// Runs the script once; prints "script.lua:LINE: message" and a traceback on error.
int run_script(lua_State* L, const sn::app::Options& opt) {
  int status = 0;
  lua_pushcfunction(L, traceback);
  if (luaL_loadfile(L, opt.script.c_str()) != 0) {
    fprintf(stderr, "%s\n", lua_tostring(L, -1));
    status = 1;
  } else {
    for (const auto& a : opt.script_args) lua_pushstring(L, a.c_str());
    if (lua_pcall(L, int(opt.script_args.size()), 0, 1) != 0) {
      fprintf(stderr, "%s\n", lua_tostring(L, -1));
      status = 1;
    }
  }
  lua_settop(L, 0);
  return status;
}

// True when the script loaded shadenet and called sn.live.show{...}: a window then stays open on it.
bool shows_a_view(lua_State* L) {
  lua_getglobal(L, "package");
  lua_getfield(L, -1, "loaded");
  lua_getfield(L, -1, "shadenet.live");
  bool has = false;
  if (lua_istable(L, -1)) {
    lua_pushstring(L, "_has_view");
    lua_rawget(L, -2);  // raw: sn.live's __index raises an error for a missing name
    has = lua_isfunction(L, -1) && lua_pcall(L, 0, 1, 0) == 0 && lua_toboolean(L, -1);
  }
  lua_settop(L, 0);
  return has;
}

}  // namespace

int main(int argc, char** argv) {
  // Images and datasets of megabytes come and go by the thousand in a sweep (a render, its
  // clamp per unseen view): kept in the heap instead of mapped and unmapped each time,
  // their pages are not zeroed by the kernel again and again.
  mallopt(M_MMAP_THRESHOLD, 256 << 20);
  mallopt(M_TRIM_THRESHOLD, 512 << 20);
  sn::app::Options opt;
  try {
    opt = sn::app::parse_options(argc, argv);
  } catch (const std::exception& e) {
    fprintf(stderr, "shadenet: %s\n%s", e.what(), sn::app::usage().c_str());
    return 2;
  }
  if (opt.help) {
    printf("%s", sn::app::usage().c_str());
    return 0;
  }
  try {
    if (opt.window) sn::gl::set_current(sn::gl::Context::window(opt.width, opt.height, "shadenet"));
    if (opt.gl_info) {  // the version's lines and more: with --version too, this (it was the version alone)
      printf("shadenet %s (build %s)\n%s", SHADENET_VERSION, sn::io::build_id(), sn::gl::info_text(sn::gl::current().info()).c_str());
      return 0;
    }
    if (opt.version) {
      const auto& info = sn::gl::current().info();
      printf("shadenet %s (build %s)\nGL renderer: %s\nGL version: %s\n", SHADENET_VERSION, sn::io::build_id(), info.renderer.c_str(),
             info.version.c_str());
      return 0;
    }
  } catch (const std::exception& e) {
    fprintf(stderr, "shadenet: %s\n", e.what());
    return 1;
  }
  lua_State* L = new_state(opt);
  if (!L) {
    fprintf(stderr, "shadenet: cannot create a Lua state\n");
    return 1;
  }
  int status = 0;
  sn::live::LiveOptions live{opt.script, opt.script_args, true, false};
  if (opt.size_given) live.width = opt.width, live.height = opt.height;
  if (opt.watch) {
    status = sn::live::run_live(L, live);
  } else {
    status = run_script(L, opt);
    // A windowed script that declared a view with sn.live.show keeps its window open on it.
    if (status == 0 && opt.window && shows_a_view(L)) {
      live.watch = false, live.already_ran = true;
      status = sn::live::run_live(L, live);
    }
  }
  lua_close(L);  // runs every __gc while the GL context still lives
  sn::gl::destroy_current();
  return status;
}

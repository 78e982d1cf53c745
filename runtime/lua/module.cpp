#include "lua/module.h"

#include <string>

#include "gl/context.h"
#include "lua/binding.h"

namespace sn::lua {

struct Embedded {
  const char* name;
  const char* path;  // under the source tree, for error messages
  const unsigned char* data;
  std::size_t size;
};
const Embedded* find_embedded(const char* name);  // generated from runtime/lua/*.lua, runtime/live/*.lua

namespace {

// registry["shadenet.type_name"](x): what an error calls x (type_name_at), for the Lua-side
// bindings' messages; an uncalled constructor gets its how-to-call hint there too.
int w_type_name(lua_State* L) {
  luaL_checkany(L, 1);
  const std::string name = type_name_at(L, 1);
  lua_pushlstring(L, name.data(), name.size());
  return 1;
}

// The C part of the module: every open_* adds its functions to one table.
int open_core(lua_State* L) {
  gl::current();  // every binding below may touch GL: make sure a context exists (headless by default)
  lua_pushcfunction(L, w_type_name);
  lua_setfield(L, LUA_REGISTRYINDEX, "shadenet.type_name");
  lua_newtable(L);
  open_context(L);
  open_buffer(L);
  open_program(L);
  open_image(L);
  open_figure(L);
  open_terminal(L);
  open_files(L);
  open_target(L);
  open_mesh(L);
  open_camera(L);
  open_draw(L);
  open_live(L);
  open_mlp(L);
  open_mlp_gl(L);
  open_dataset(L);
  open_dataset_sample(L);
  open_train(L);
  open_activation(L);
  open_encoding(L);
  open_lighting(L);
  open_scene(L);
  return 1;
}

// package.loaders entry for embedded Lua modules ("shadenet", "shadenet.plot", ...).
int load_embedded(lua_State* L) {
  const char* name = luaL_checkstring(L, 1);
  const Embedded* e = find_embedded(name);
  if (!e) {
    lua_pushfstring(L, "\n\tno embedded module '%s'", name);
    return 1;
  }
  std::string chunk = std::string("@") + e->path;
  if (luaL_loadbuffer(L, reinterpret_cast<const char*>(e->data), e->size, chunk.c_str()) != 0) return lua_error(L);
  return 1;
}

}  // namespace

void install(lua_State* L) {
  // package.preload["shadenet.core"] = the C table; the embedded shadenet.lua requires it.
  lua_getglobal(L, "package");
  lua_getfield(L, -1, "preload");
  lua_pushcfunction(L, wrap<open_core>);  // a context that cannot be made is a Lua error, not a crash
  lua_setfield(L, -2, "shadenet.core");
  lua_pop(L, 1);
  lua_getfield(L, -1, "loaders");
  int n = int(lua_objlen(L, -1));
  // Insert after the preload searcher so embedded modules win over stray files on disk.
  for (int i = n; i >= 2; --i) {
    lua_rawgeti(L, -1, i);
    lua_rawseti(L, -2, i + 1);
  }
  lua_pushcfunction(L, load_embedded);
  lua_rawseti(L, -2, 2);
  lua_pop(L, 2);
}

}  // namespace sn::lua

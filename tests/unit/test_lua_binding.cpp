// What a C++ function bound to Lua (lua/binding.h) turns an exception into.
#include <gtest/gtest.h>

#include <lua.hpp>

#include <new>
#include <stdexcept>
#include <string>

#include "lua/binding.h"

namespace {

int throws_bad_alloc(lua_State*) { throw std::bad_alloc(); }
int throws_invalid(lua_State*) { throw std::invalid_argument("sn.thing: a reason"); }

std::string error_of(lua_State* L, lua_CFunction f) {
  lua_pushcfunction(L, f);
  lua_setglobal(L, "f");
  EXPECT_NE(luaL_dostring(L, "f()"), 0);
  std::string e = lua_tostring(L, -1);
  lua_pop(L, 1);
  return e;
}

}  // namespace

// Out of memory says so, and what would help (its what() is only "std::bad_alloc"); other
// errors keep their text; both name the script's line.
TEST(LuaBinding, ExceptionsBecomeErrorsAtTheScriptsLine) {
  lua_State* L = luaL_newstate();
  luaL_openlibs(L);
  EXPECT_EQ(error_of(L, sn::lua::wrap<throws_invalid>), "[string \"f()\"]:1: sn.thing: a reason");
  const std::string oom = error_of(L, sn::lua::wrap<throws_bad_alloc>);
  EXPECT_EQ(oom.rfind("[string \"f()\"]:1: out of memory: the process could not allocate what this call needs", 0), 0u)
      << oom;
  EXPECT_NE(oom.find("ulimit -v"), std::string::npos);
  lua_close(L);
}

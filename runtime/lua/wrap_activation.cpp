// sn.activation: a user's activation (GLSL + Lua twins) into the registry of nn/activation.h,
// and the names valid in each position.
#include <string>

#include "lua/binding.h"
#include "lua/module.h"
#include "nn/activation_define.h"

namespace sn::lua {

namespace {

// A Lua function as a double twin, called on the Lua thread of the binding running now (never a
// coroutine that defined it and may have ended; the cpu backend runs the translated GLSL, never
// the twins).
std::function<double(double, double)> lua_twin(lua_State* defined_on, int ref, const std::string& what) {
  return [defined_on, ref, what](double z, double) {
    lua_State* L = running_state(defined_on);
    lua_rawgeti(L, LUA_REGISTRYINDEX, ref);
    lua_pushnumber(L, z);
    pcall_or_throw(L, 1, 1, what);
    if (lua_type(L, -1) != LUA_TNUMBER) {
      std::string t = luaL_typename(L, -1);
      lua_pop(L, 1);
      throw std::invalid_argument(what + " returned a " + t + ", not a number");
    }
    const double v = lua_tonumber(L, -1);
    lua_pop(L, 1);
    return v;
  };
}

int function_ref(lua_State* L, const Options& o, const char* key) {
  const int at = o.push(key);
  if (!lua_isfunction(L, at)) throw Error(o.where(key) + ": function expected, got " + type_name_at(L, at));
  return luaL_ref(L, LUA_REGISTRYINDEX);  // pops it
}

// sn.activation.define{ name, glsl = "GLSL of x", grad = "GLSL of x", lua = function(x), lua_grad = function(x) }
int w_define(lua_State* L) {
  Options o(L, 1, "sn.activation.define", {"name", "glsl", "grad", "lua", "lua_grad"});
  nn::ActivationDef d;
  d.name = o.string("name");
  d.glsl = o.string("glsl");
  d.grad = o.string("grad");
  d.origin = caller_line(L) + "activation " + d.name;
  d.f = lua_twin(L, function_ref(L, o, "lua"), "activation '" + d.name + "': lua");
  d.df = lua_twin(L, function_ref(L, o, "lua_grad"), "activation '" + d.name + "': lua_grad");
  try {
    nn::define_activation(std::move(d));
  } catch (const std::exception& e) {
    throw Error(std::string("sn.activation.define: ") + e.what());
  }
  return 0;
}

// sn.activation.names("hidden" | "output") -> the names sn.mlp accepts there
int w_names(lua_State* L) {
  const std::string where = luaL_optstring(L, 1, "hidden");
  if (where != "hidden" && where != "output") throw Error("sn.activation.names: 'hidden' or 'output' expected, got '" + where + "'");
  const auto names = nn::activation_names(where == "hidden" ? nn::Position::hidden : nn::Position::output);
  push_strings(L, names);
  return 1;
}

// sn.activation.key(name) -> a user definition's key (its GLSL hashed), nil for a built-in
int w_key(lua_State* L) {
  const nn::ActivationDef& d = nn::activation_def(nn::parse_activation(check_string(L, 1, "sn.activation.key name")));
  push_definition_key(L, d.simd >= 0 ? std::vector<std::string>{}
                                      : std::vector<std::string>{d.glsl, d.grad, d.grad_from_output});
  return 1;
}

}  // namespace

void open_activation(lua_State* L) {
  static const luaL_Reg fns[] = {SN_FN("define", w_define), SN_FN("names", w_names), SN_FN("key", w_key),
                                 {nullptr, nullptr}};
  lua_newtable(L);
  luaL_register(L, nullptr, fns);
  lua_setfield(L, -2, "activation");
}

}  // namespace sn::lua

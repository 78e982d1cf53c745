// sn.encoding: the input encodings of nn/encoding.h as scripts write them in sn.mlp{ encoding =
// {...} }, and the names of those registered.
#include <algorithm>
#include <string>

#include "lua/encoding_binding.h"
#include "lua/module.h"
#include "scene/gbuffer.h"

namespace sn::lua {

int InputGroups::offset(std::size_t i) const {
  int o = 0;
  for (std::size_t k = 0; k < i; ++k) o += widths[k];
  return o;
}

int InputGroups::total() const { return offset(widths.size()); }

int input_width(const std::string& name) {
  const auto& attrs = scene::gbuffer_attribute_names();
  if (std::find(attrs.begin(), attrs.end(), name) != attrs.end()) return scene::attribute_width(name);
  return 1;
}

namespace {

// The options an encoding takes, for messages: "bands, include_input".
std::string options_of(const nn::EncodingDef& d) {
  std::vector<std::string> o;
  if (!d.count.empty()) o.push_back(d.count);
  if (d.has_include_input) o.push_back("include_input");
  if (d.has_range) o.push_back("range");
  return o.empty() ? std::string("no options") : join(o);
}

nn::InputEncoding check_one(lua_State* L, int idx, const std::string& input, int offset, int width,
                            const std::string& what) {
  const std::string who = what + " of input '" + input + "'";
  std::string name;
  const bool table = lua_istable(L, idx);
  if (table) {
    lua_rawgeti(L, idx, 1);
    if (lua_type(L, -1) != LUA_TSTRING)
      throw Error(who + ": the encoding's name first, e.g. { \"frequency\", bands = 8 }, got " + type_name_at(L, -1));
    name = check_string(L, -1, who.c_str());
    lua_pop(L, 1);
  } else if (lua_type(L, idx) == LUA_TSTRING) {
    name = check_string(L, idx, who.c_str());
  } else {
    throw Error(who + ": an encoding name or { name, options } expected, got " + type_name_at(L, idx));
  }
  nn::Encoding kind;
  try {
    kind = nn::parse_encoding(name);
  } catch (const std::invalid_argument& e) {
    throw Error(who + ": " + e.what());
  }
  const nn::EncodingDef& d = nn::encoding_def(kind);
  nn::InputEncoding e = nn::default_encoding(kind, input, offset, width);
  if (table) {
    lua_pushnil(L);
    while (lua_next(L, idx)) {
      // key at -2, value at -1
      if (lua_type(L, -2) == LUA_TNUMBER && lua_tonumber(L, -2) == 1) {
        lua_pop(L, 1);
        continue;
      }
      std::string key = "[";
      if (lua_type(L, -2) == LUA_TSTRING) key = lua_tostring(L, -2);
      else key.append(type_name_at(L, -2)).append("]");
      const std::string where = who + " option '" + key + "'";
      if (!d.count.empty() && key == d.count) {
        e.n = check_int32(L, -1, where.c_str());
      } else if (d.has_include_input && key == "include_input") {
        if (!lua_isboolean(L, -1)) throw Error(where + ": boolean expected, got " + type_name_at(L, -1));
        e.include_input = lua_toboolean(L, -1);
      } else if (d.has_range && key == "range") {
        const auto r = check_numbers(L, -1, where.c_str(), 2);
        e.lo = r[0], e.hi = r[1];
      } else {
        throw Error(who + ": '" + name + "' takes " + options_of(d) + ", not '" + key + "'");
      }
      lua_pop(L, 1);
    }
  }
  try {
    nn::check(e);
  } catch (const std::invalid_argument& ex) {
    throw Error(what + ": " + ex.what());
  }
  return e;
}

// sn.encoding.names() -> the encodings sn.mlp accepts
int w_names(lua_State* L) {
  push_strings(L, nn::encoding_names());
  return 1;
}

}  // namespace

std::vector<nn::InputEncoding> check_encodings(lua_State* L, int idx, const InputGroups& groups, const std::string& what) {
  idx = absindex(L, idx);
  if (!lua_istable(L, idx))
    throw Error(what + ": { input = encoding, ... } expected, got " + type_name_at(L, idx));
  std::vector<nn::InputEncoding> out;
  lua_pushnil(L);
  while (lua_next(L, idx)) {
    if (lua_type(L, -2) != LUA_TSTRING)
      throw Error(what + ": keys are input names ({ uv = { \"frequency\", bands = 8 } }), got a " + type_name_at(L, -2) +
                  " key");
    const std::string input = lua_tostring(L, -2);
    if (groups.names.empty())
      throw Error(what + ": encodings are given per named input, and this network's inputs have no names; name them, "
                  "e.g. inputs = { \"normal\", \"view\", \"uv\" }");
    const auto at = std::find(groups.names.begin(), groups.names.end(), input);
    if (at == groups.names.end())
      throw Error(what + ": the network has no input '" + input + "' (its inputs: " + join(groups.names) + ")");
    const std::size_t i = std::size_t(at - groups.names.begin());
    nn::InputEncoding e = check_one(L, lua_gettop(L), input, groups.offset(i), groups.widths[i], what);
    if (e.kind != nn::Encoding::identity) out.push_back(std::move(e));
    lua_pop(L, 1);
  }
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.offset < b.offset; });
  return out;
}

void push_encodings(lua_State* L, const std::vector<nn::InputEncoding>& encodings) {
  lua_createtable(L, 0, int(encodings.size()));
  for (const auto& e : encodings) {
    const nn::EncodingDef& d = nn::encoding_def(e.kind);
    lua_createtable(L, 1, 2);
    lua_pushstring(L, d.name.c_str());
    lua_rawseti(L, -2, 1);
    if (!d.count.empty()) {
      lua_pushinteger(L, e.n);
      lua_setfield(L, -2, d.count.c_str());
    }
    if (d.has_include_input) {
      lua_pushboolean(L, e.include_input);
      lua_setfield(L, -2, "include_input");
    }
    if (d.has_range) {
      lua_createtable(L, 2, 0);
      lua_pushnumber(L, e.lo);
      lua_rawseti(L, -2, 1);
      lua_pushnumber(L, e.hi);
      lua_rawseti(L, -2, 2);
      lua_setfield(L, -2, "range");
    }
    lua_setfield(L, -2, e.input.c_str());
  }
}

void open_encoding(lua_State* L) {
  static const luaL_Reg fns[] = {SN_FN("names", w_names), {nullptr, nullptr}};
  lua_newtable(L);
  luaL_register(L, nullptr, fns);
  lua_setfield(L, -2, "encoding");
}

}  // namespace sn::lua

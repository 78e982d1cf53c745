// sn.encoding: the input encodings of nn/encoding.h as scripts write them in sn.mlp{ encoding =
// {...} }, a user's own (sn.encoding.define: GLSL + a Lua twin), and the names registered.
#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "lua/encoding_binding.h"
#include "lua/module.h"
#include "nn/encoding_define.h"
#include "scene/gbuffer.h"

namespace sn::lua {

int InputGroups::offset(std::size_t i) const {
  int o = 0;
  for (std::size_t k = 0; k < i; ++k) o += widths[k];
  return o;
}

int InputGroups::total() const { return offset(widths.size()); }

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

// The twin of a user's encoding: lua(x, n, include_input, range) -> { outputs } for the w
// components x[1..w], called on the Lua thread of the binding running now (the encoding is
// marked caller_thread, so nothing calls it from another thread).
std::function<void(const nn::InputEncoding&, const double*, double*)> lua_row_twin(lua_State* defined_on, int ref,
                                                                                  const std::string& name) {
  return [defined_on, ref, name](const nn::InputEncoding& e, const double* x, double* out) {
    lua_State* L = running_state(defined_on);
    const int outputs = e.out_width();
    const std::string what = "encoding '" + name + "': lua";
    lua_rawgeti(L, LUA_REGISTRYINDEX, ref);
    lua_createtable(L, e.width, 0);
    for (int c = 0; c < e.width; ++c) {
      lua_pushnumber(L, x[c]);
      lua_rawseti(L, -2, c + 1);
    }
    lua_pushinteger(L, e.n);
    lua_pushboolean(L, e.include_input);
    lua_createtable(L, 2, 0);
    lua_pushnumber(L, e.lo);
    lua_rawseti(L, -2, 1);
    lua_pushnumber(L, e.hi);
    lua_rawseti(L, -2, 2);
    pcall_or_throw(L, 4, 1, what);
    const int got = lua_istable(L, -1) ? int(lua_objlen(L, -1)) : -1;
    if (got != outputs) {
      const std::string t = got < 0 ? std::string("a ") + luaL_typename(L, -1) : std::to_string(got) + " numbers";
      lua_pop(L, 1);
      throw std::invalid_argument(what + " returned " + t + "; outputs says " + std::to_string(outputs) + " for an input of " +
                                  std::to_string(e.width));
    }
    for (int j = 0; j < outputs; ++j) {
      lua_rawgeti(L, -1, j + 1);
      if (lua_type(L, -1) != LUA_TNUMBER) {
        const std::string t = luaL_typename(L, -1);
        lua_pop(L, 2);
        throw std::invalid_argument(what + " returned a " + t + " as output " + std::to_string(j + 1) + ", not a number");
      }
      out[j] = lua_tonumber(L, -1);
      lua_pop(L, 1);
      // Checked here, where the encoding and its input are known: downstream the value only
      // showed as a network output of -inf, or a training "diverged" at step 1.
      if (!std::isfinite(out[j])) {
        std::string input;
        for (int c = 0; c < e.width; ++c) input += (c ? ", " : "") + io::number_text(x[c]);
        lua_pop(L, 1);
        throw std::invalid_argument(what + " returned " + io::number_text(out[j]) + " as output " + std::to_string(j + 1) +
                                    " for the input {" + input + "}; an encoding's outputs must be finite");
      }
    }
    lua_pop(L, 1);
  };
}

// sn.encoding.define{ name, glsl = "body: output j of x", lua = function(x, n, include_input, range),
//                     outputs = n | function(w, n, include_input), count = { "bands", min, max, default },
//                     include_input = default, range = true, input_width = w }
int w_define(lua_State* L) {
  Options o(L, 1, "sn.encoding.define",
            {"name", "glsl", "lua", "outputs", "count", "include_input", "range", "input_width"});
  nn::EncodingDef d;
  d.name = o.string("name");
  d.glsl = o.string("glsl");
  d.origin = caller_line(L) + "encoding " + d.name;
  d.caller_thread = true;
  d.input_width = o.int32("input_width", 0);
  if (d.input_width < 0 || d.input_width > 4) throw Error(o.where("input_width") + ": 1..4 (or none: any width)");
  d.has_include_input = o.has("include_input");
  d.include_input_default = o.boolean("include_input", false);
  d.has_range = o.boolean("range", false);
  const int count = o.push("count");
  if (!lua_isnil(L, count)) {
    const std::string where = o.where("count");
    if (!lua_istable(L, count))
      throw Error(where + ": { name, min = .., max = .., default = .. } expected, got " + type_name_at(L, count));
    d.count_min = 1;
    d.count_max = d.count_default = -1;
    lua_pushnil(L);
    while (lua_next(L, count)) {
      const std::string key = lua_type(L, -2) == LUA_TSTRING ? lua_tostring(L, -2) : "";
      const bool first = lua_type(L, -2) == LUA_TNUMBER && lua_tonumber(L, -2) == 1;
      if (first && lua_type(L, -1) == LUA_TSTRING) d.count = lua_tostring(L, -1);
      else if (key == "min") d.count_min = check_int32(L, -1, (where + " min").c_str());
      else if (key == "max") d.count_max = check_int32(L, -1, (where + " max").c_str());
      else if (key == "default") d.count_default = check_int32(L, -1, (where + " default").c_str());
      else throw Error(where + ": valid entries are [1] = the option's name (\"bands\"), min, max and default");
      lua_pop(L, 1);
    }
    if (d.count_max < 0) throw Error(where + ": max is required");
    if (d.count_default < 0) d.count_default = d.count_min;
    if (d.count == "include_input" || d.count == "range" || d.count.empty())
      throw Error(o.where("count") + ": '" + d.count + "' cannot name the count");
    if (!(d.count_min >= 1 && d.count_min <= d.count_default && d.count_default <= d.count_max && d.count_max <= 64))
      throw Error(o.where("count") + ": needs 1 <= min <= default <= max <= 64, got min " + std::to_string(d.count_min) +
                  ", default " + std::to_string(d.count_default) + ", max " + std::to_string(d.count_max));
  }
  lua_pop(L, 1);
  // The output count of every case the encoding accepts, taken once here: widths are read on any
  // thread, where Lua cannot run.
  std::map<std::tuple<int, int, bool>, int> widths;
  const int outputs = o.push("outputs");
  const bool fixed = lua_type(L, outputs) == LUA_TNUMBER;
  if (!fixed && !lua_isfunction(L, outputs))
    throw Error(o.where("outputs") + ": a number or function(w, n, include_input) expected, got " +
                type_name_at(L, outputs));
  for (int w = 1; w <= 4; ++w) {
    if (d.input_width && w != d.input_width) continue;
    for (int n = d.count.empty() ? 0 : d.count_min; n <= (d.count.empty() ? 0 : d.count_max); ++n)
      for (bool keep : {false, true}) {
        if (keep && !d.has_include_input) continue;
        int v;
        if (fixed) {
          v = check_int32(L, outputs, o.where("outputs").c_str());
        } else {
          lua_pushvalue(L, outputs);
          lua_pushinteger(L, w);
          lua_pushinteger(L, n);
          lua_pushboolean(L, keep);
          pcall_or_throw(L, 3, 1, "sn.encoding.define option 'outputs'");
          v = lua_type(L, -1) == LUA_TNUMBER ? check_int32(L, -1, o.where("outputs").c_str()) : -1;
          lua_pop(L, 1);
        }
        widths[{w, n, keep}] = v;
      }
  }
  lua_pop(L, 1);
  d.out_width = [widths](int w, int n, bool keep) {
    const auto it = widths.find({w, n, keep});
    return it == widths.end() ? 0 : it->second;
  };
  const int fn = o.push("lua");
  if (!lua_isfunction(L, fn)) throw Error(o.where("lua") + ": function expected, got " + type_name_at(L, fn));
  d.twin_fingerprint = function_fingerprint(L, fn);
  d.f_row = lua_row_twin(L, luaL_ref(L, LUA_REGISTRYINDEX), d.name);
  d.f = [row = d.f_row](const nn::InputEncoding& e, const double* x, int j) {
    std::vector<double> out(static_cast<std::size_t>(e.out_width()));
    row(e, x, out.data());
    return out[std::size_t(j)];
  };
  try {
    nn::define_encoding(std::move(d));
  } catch (const std::exception& e) {
    throw Error(std::string("sn.encoding.define: ") + e.what());
  }
  return 0;
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

// sn.encoding.key(name) -> a user definition's key, nil for a built-in: everything that changes
// what a network sees: the GLSL, the count option, include_input and its default, range, the
// input width, the output count of every case (outputs' values, not its text) and the twin the
// cpu backend encodes with. (Its GLSL and count alone reused a sweep's runs after include_input's
// default, outputs or the twin changed.)
int w_key(lua_State* L) {
  const nn::Encoding e = nn::parse_encoding(check_string(L, 1, "sn.encoding.key name"));
  const nn::EncodingDef& d = nn::encoding_def(e);
  if (nn::is_builtin(e)) {
    push_definition_key(L, {});
    return 1;
  }
  std::string outputs;
  const bool counted = !d.count.empty();
  for (int w = 1; w <= 4; ++w) {
    if (d.input_width && w != d.input_width) continue;
    for (int n = counted ? d.count_min : 0; n <= (counted ? d.count_max : 0); ++n)
      for (bool keep : {false, true})
        if (!keep || d.has_include_input) outputs += " " + std::to_string(d.out_width(w, n, keep));
  }
  push_definition_key(L, {d.glsl, "count " + d.count + " " + std::to_string(d.count_min) + " " +
                                      std::to_string(d.count_max) + " " + std::to_string(d.count_default),
                          "input_width " + std::to_string(d.input_width),
                          std::string("include_input ") + (d.has_include_input ? "yes " : "no ") +
                              (d.include_input_default ? "true" : "false"),
                          std::string("range ") + (d.has_range ? "yes" : "no"), "outputs" + outputs,
                          "twin " + d.twin_fingerprint});
  return 1;
}

void open_encoding(lua_State* L) {
  static const luaL_Reg fns[] = {SN_FN("define", w_define), SN_FN("names", w_names), SN_FN("key", w_key),
                                 {nullptr, nullptr}};
  lua_newtable(L);
  luaL_register(L, nullptr, fns);
  lua_setfield(L, -2, "encoding");
}

}  // namespace sn::lua

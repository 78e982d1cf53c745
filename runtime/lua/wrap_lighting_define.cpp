// sn.lighting.define{...}: a lighting model from Lua + GLSL, registered exactly like the
// built-ins (shading/lighting_model.h), and sn.lighting.check(model), which holds its GPU shader
// to its twin. The twin of a defined model is a Lua function, called per point.
#include <algorithm>
#include <cmath>
#include <filesystem>

#include "gl/shader_source.h"
#include "io/text.h"
#include "lua/binding.h"
#include "lua/lighting_binding.h"
#include "shading/lighting.h"
#include "shading/lighting_gpu.h"
#include "shading/stress.h"

namespace sn::lua {

namespace fs = std::filesystem;

namespace {

void set_vec3(lua_State* L, const char* key, const glm::dvec3& v) {
  push_vec3(L, v);
  lua_setfield(L, -2, key);
}

void push_surface(lua_State* L, const shading::Surface& s) {
  lua_createtable(L, 0, 10);
  set_vec3(L, "n", s.n);
  set_vec3(L, "v", s.v);
  set_vec3(L, "l", s.l);
  set_vec3(L, "light_color", s.light_color);
  set_vec3(L, "base_color", s.base_color);
  lua_createtable(L, 2, 0);
  lua_pushnumber(L, s.uv.x), lua_rawseti(L, -2, 1);
  lua_pushnumber(L, s.uv.y), lua_rawseti(L, -2, 2);
  lua_setfield(L, -2, "uv");
  set_vec3(L, "position", s.position);
  set_vec3(L, "world_position", s.world_position);
  set_vec3(L, "tangent", s.tangent);
  set_vec3(L, "bitangent", s.bitangent);
}

void push_params(lua_State* L, const shading::LightingParams& p) {
  const auto& spec = p.spec();
  lua_createtable(L, 0, int(spec.params.size()));
  for (std::size_t i = 0; i < spec.params.size(); ++i) {
    int n = spec.params[i].components;
    if (n == 1) {
      lua_pushnumber(L, p.values[i][0]);
    } else {
      lua_createtable(L, n, 0);
      for (int c = 0; c < n; ++c) lua_pushnumber(L, p.values[i][c]), lua_rawseti(L, -2, c + 1);
    }
    lua_setfield(L, -2, spec.params[i].name.c_str());
  }
}

// Calls the Lua function under registry `ref` with the arguments push_args() pushes and reads
// the {r, g, b} it returns. A Lua error or a wrong shape is an exception naming `what`; so is a
// NaN or infinity when `finite` (a bound), else it comes back as it is (the stress test counts a
// twin's).
template <class PushArgs>
glm::dvec3 call_rgb(lua_State* L, int ref, const std::string& what, bool finite, PushArgs push_args) {
  int top = lua_gettop(L);
  if (!lua_checkstack(L, 8)) throw Error(what + ": no Lua stack space left to call it");
  lua_rawgeti(L, LUA_REGISTRYINDEX, ref);
  int nargs = push_args();
  pcall_or_throw(L, nargs, 1, what);  // counts the nesting: a twin calling its own model:shade
  glm::dvec3 out;
  bool ok = lua_istable(L, -1) && lua_objlen(L, -1) == 3;
  for (int c = 0; ok && c < 3; ++c) {
    lua_rawgeti(L, -1, c + 1);
    ok = lua_type(L, -1) == LUA_TNUMBER;
    if (ok) out[c] = lua_tonumber(L, -1);
    lua_pop(L, 1);
  }
  std::string got = ok ? "" : type_name_at(L, -1);
  lua_settop(L, top);
  if (!ok) throw Error(what + " must return {r, g, b} (3 numbers), got " + got);
  if (finite && !(std::isfinite(out.x) && std::isfinite(out.y) && std::isfinite(out.z)))
    throw Error(what + " returned " + io::vec3_text(out) + "; it must be finite");
  return out;
}

// The twin of a defined model: twin(surface, params) -> {r, g, b}.
struct LuaTwin {
  lua_State* L;
  int ref;
  std::string name;
  glm::dvec3 operator()(const shading::Surface& s, const shading::LightingParams& p) const {
    lua_State* T = running_state(L);
    return call_rgb(T, ref, "lighting model '" + name + "': its twin", false, [&] {
      push_surface(T, s);
      push_params(T, p);
      return 2;
    });
  }
};

// The optional bound of a defined model: bound(params, light) -> {r, g, b}.
struct LuaBound {
  lua_State* L;
  int ref;
  std::string name;
  glm::dvec3 operator()(const shading::LightingParams& p, const scene::Light& light) const {
    lua_State* T = running_state(L);
    return call_rgb(T, ref, "lighting model '" + name + "': its bound", true, [&] {
      push_params(T, p);
      push_light(T, light);
      return 2;
    });
  }
};

// Where the script calling sn.lighting.define is: "file.lua:LINE" and the file's folder (through
// pcall too: the nearest Lua function). The console's lines have no file: the working directory.
void caller(lua_State* L, std::string& where, std::string& dir) {
  lua_Debug ar;
  where = "sn.lighting.define", dir = ".";
  int level = 1;
  while (lua_getstack(L, level, &ar) && lua_getinfo(L, "S", &ar) && ar.what[0] == 'C') ++level;
  if (lua_getstack(L, level, &ar) && lua_getinfo(L, "Sl", &ar) && ar.source[0] == '@') {
    where = std::string(ar.source + 1) + ":" + std::to_string(ar.currentline);
    dir = fs::path(ar.source + 1).parent_path().string();
    if (dir.empty()) dir = ".";
  }
}

// params = { name = { default = x | {r,g,b}, range = {min, max}, type = "number"|"rgb"|"vec4", doc = "..." } }
std::vector<shading::ParamSpec> read_param_schema(lua_State* L, int idx, const std::string& who) {
  std::vector<shading::ParamSpec> out;
  if (lua_isnil(L, idx)) return out;
  if (!lua_istable(L, idx)) throw Error(who + ": 'params' must be a table { name = { default = ..., range = {min, max} } }");
  lua_pushnil(L);
  while (lua_next(L, idx)) {
    if (lua_type(L, -2) != LUA_TSTRING) throw Error(who + ": 'params' keys must be parameter names");
    std::string name = lua_tostring(L, -2);
    std::string what = who + " parameter '" + name + "'";
    Options o(L, lua_gettop(L), what.c_str(), {"default", "range", "type", "doc"});
    shading::ParamSpec ps{name, 1, {0, 0, 0, 0}, 0, 0, o.string("doc", name)};
    if (!o.has("default")) throw Error(what + ": 'default' is required");
    int d = o.push("default");
    std::vector<double> def = lua_type(L, d) == LUA_TNUMBER ? std::vector<double>{lua_tonumber(L, d)}
                                                             : check_numbers(L, d, (what + " default").c_str());
    lua_pop(L, 1);
    int type = o.choice("type", {"number", "rgb", "vec4"}, def.size() == 3 ? 1 : def.size() == 4 ? 2 : 0);
    ps.components = type == 0 ? 1 : type == 1 ? 3 : 4;
    if (def.size() == 1 && ps.components == 3) def = {def[0], def[0], def[0]};
    if (int(def.size()) != ps.components)
      throw Error(what + ": the default has " + std::to_string(def.size()) + " numbers, its type '" +
                  (type == 0 ? "number" : type == 1 ? "rgb" : "vec4") + "' needs " + std::to_string(ps.components));
    for (int c = 0; c < ps.components; ++c) ps.def[c] = def[c];
    if (!o.has("range")) throw Error(what + ": 'range' = {min, max} is required (the valid values)");
    auto range = o.numbers("range", 2);
    ps.min = range[0], ps.max = range[1];
    out.push_back(ps);
    lua_pop(L, 1);
  }
  // Lua tables have no order: parameters are kept sorted by name, so the struct is stable.
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  return out;
}

// The GLSL against the twin (shading::hold_twin) where define holds it; throws naming the worst
// point, the parameters and both values.
void hold_to_twin(const shading::ModelPtr& m, const std::string& who) {
  const scene::Light light = shading::hold_light();
  shading::TwinMismatch miss;
  shading::LightingParams p;
  for (const auto& params : shading::hold_params(m))
    if ((miss = shading::hold_twin(params, light)).failed) {
      p = params;
      break;
    }
  if (!miss.failed) return;
  const shading::Surface& s = miss.at;
  std::string at = "normal " + io::vec3_text(s.n) + ", view " + io::vec3_text(s.v);
  for (const auto& a : p.spec().attributes) {
    if (a == "base_color") at += ", base " + io::vec3_text(s.base_color);
    else if (a == "uv") at += ", uv {" + io::number_text(s.uv.x) + ", " + io::number_text(s.uv.y) + "}";
    else if (a == "position") at += ", position " + io::vec3_text(s.position);
    else if (a == "world_position") at += ", world_position " + io::vec3_text(s.world_position);
    else if (a == "tangent") at += ", tangent " + io::vec3_text(s.tangent);
    else if (a == "bitangent") at += ", bitangent " + io::vec3_text(s.bitangent);
  }
  throw Error(who + ": its GLSL gives " + io::vec3_text(miss.gpu) + " and its twin " + io::vec3_text(miss.twin) + " for " +
              p.describe() + " at " + at + ", light {dir = " + io::vec3_text(light.dir) + ", color = " + io::vec3_text(light.color) +
              "}: the twin must compute what the GLSL does (within " + io::number_text(shading::kHoldTolerance) +
              " relative, as sn.lighting.check measures), since model:shade and the checks take it for the GLSL");
}

}  // namespace

// sn.lighting.define{ name, params, glsl, attributes, twin, bound } -> Lighting at the defaults
int w_define(lua_State* L) {
  Options o(L, 1, "sn.lighting.define", {"name", "params", "glsl", "attributes", "twin", "bound"});
  std::string where, dir;
  caller(L, where, dir);
  shading::LightingModel m;
  if (!o.has("name")) throw Error("sn.lighting.define: 'name' is required");
  m.name = o.string("name");
  const std::string who = "sn.lighting.define '" + m.name + "'";
  if (lighting_function_name(m.name))
    throw Error(who + ": the name is taken by the function sn.lighting." + m.name + "; choose another name");
  int pi = o.push("params");
  m.params = read_param_schema(L, pi, who);
  lua_pop(L, 1);
  if (o.has("attributes")) {
    int ai = o.push("attributes");
    if (!lua_istable(L, ai)) throw Error(who + ": 'attributes' must be a list of names");
    const int n = check_list(L, ai, who + " 'attributes'");
    for (int i = 1; i <= n; ++i) {
      lua_rawgeti(L, ai, i);
      m.attributes.push_back(check_string(L, -1, (who + " attribute").c_str()));
      lua_pop(L, 1);
    }
    lua_pop(L, 1);
  }
  if (!o.has("glsl"))
    throw Error(who + ": 'glsl' is required: a .glsl file or source text defining vec3 shade(Surface s, Params p)");
  // The GLSL is fixed now, #included files and all: the model checked below is the one that
  // renders, however the files change later (defining it again reads them anew).
  std::string glsl = o.string("glsl");
  gl::CapturedSource src;
  if (glsl.size() > 5 && glsl.compare(glsl.size() - 5, 5, ".glsl") == 0 && glsl.find('\n') == std::string::npos) {
    fs::path beside = fs::path(dir) / glsl;
    std::string path = beside.string();
    if (!fs::exists(beside)) {
      try {
        path = gl::resolve_shader_path(glsl);
      } catch (const std::exception&) {
        throw Error(who + ": glsl file '" + glsl + "' not found (looked beside the script in " + gl::display_path(dir) +
                    "/, in the working directory and in shaders/)");
      }
    }
    src = gl::capture_file(path);
  } else {
    src = gl::capture_source(where + " (glsl of " + m.name + ")", glsl, dir);  // #includes beside the script
  }
  m.glsl_source = std::move(src.text);
  m.glsl_name = std::move(src.name);
  m.glsl_includes = std::move(src.files);
  int ti = o.push("twin");
  if (!lua_isfunction(L, ti))
    throw Error(who + ": 'twin' is required: function(s, p) returning {r, g, b} in double precision "
                "(model:shade and sn.lighting.check use it)");
  m.twin = LuaTwin{L, luaL_ref(L, LUA_REGISTRYINDEX), m.name};  // luaL_ref pops it
  if (o.has("bound")) {
    int bi = o.push("bound");
    if (!lua_isfunction(L, bi))
      throw Error(who + ": 'bound' must be a function(p, light) returning {r, g, b}, the largest raw value per channel");
    m.bound = LuaBound{L, luaL_ref(L, LUA_REGISTRYINDEX), m.name};
  }

  // Everything is checked before the model is registered: the schema and attributes, the twin
  // at one point, the GLSL compiled once (its errors at its own file:line), then the GLSL held to
  // the twin over the domain.
  shading::validate_model(m);
  shading::LightingParams p;
  p.model = std::make_shared<const shading::LightingModel>(m);
  for (const auto& ps : m.params) p.values.push_back(ps.def);
  shading::Surface s = shading::make_surface(scene::Light{}, {0, 1, 0}, {0.6, 0.8, 0});
  s.tangent = {1, 0, 0}, s.bitangent = {0, 0, -1};
  glm::dvec3 c = m.twin(s, p);
  if (!(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z)))
    throw Error(who + ": its twin returned " + io::vec3_text(c) + " at normal {0, 1, 0}, view {0.6, 0.8, 0}: it must be finite");
  shading::compile_lighting(m);
  hold_to_twin(p.model, who);
  shading::register_model(m);
  auto model = shading::find_model(m.name);
  lua_pushnil(L);  // no parameters: the defaults
  return make_lighting(L, model, lua_gettop(L));
}

// sn.lighting.check(model [, lights]) -> { max_difference, compared, skipped, worst = {...} }
int w_check(lua_State* L) {
  const auto& p = check_lighting(L, 1, "sn.lighting.check model");
  auto c = shading::check_twin(p, check_lights(L, 2, "sn.lighting.check"));
  lua_createtable(L, 0, 4);
  lua_pushnumber(L, c.max_difference), lua_setfield(L, -2, "max_difference");
  lua_pushinteger(L, lua_Integer(c.compared)), lua_setfield(L, -2, "compared");
  lua_pushinteger(L, lua_Integer(c.skipped)), lua_setfield(L, -2, "skipped");
  lua_createtable(L, 0, 4);
  set_vec3(L, "normal", c.worst.n);
  set_vec3(L, "view", c.worst.v);
  set_vec3(L, "gpu", c.worst_gpu);
  set_vec3(L, "twin", c.worst_twin);
  lua_setfield(L, -2, "worst");
  return 1;
}

}  // namespace sn::lua

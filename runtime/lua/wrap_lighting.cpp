// sn.lighting.*: the ground-truth lighting models as "Lighting" objects (parameters checked
// against their domains), evaluated by the CPU twin (model:shade) or on the GPU
// (model:evaluate); sn.lighting.stress runs the numerical stress test; sn.color.* converts
// between colour spaces.
#include <cmath>
#include <map>

#include "gl/buffer.h"
#include "gl/shader_source.h"
#include "io/text.h"
#include "lua/binding.h"
#include "lua/lighting_binding.h"
#include "lua/module.h"
#include "shading/color.h"
#include "shading/lighting.h"
#include "shading/lighting_gpu.h"
#include "shading/render_truth.h"
#include "shading/stress.h"

namespace sn::lua {

using scene::Light;
using shading::LightingParams;

void push_vec3(lua_State* L, const glm::dvec3& v) {
  lua_createtable(L, 3, 0);
  for (int i = 0; i < 3; ++i) {
    lua_pushnumber(L, v[i]);
    lua_rawseti(L, -2, i + 1);
  }
}

LightingParams& check_lighting(lua_State* L, int idx, const std::string& what) {
  if (!test_type(L, idx, kLightingType)) {
    std::string got;
    if (lua_type(L, idx) != LUA_TSTRING) {
      got = type_name_at(L, idx);
    } else {  // a model's name: say how to make the model
      const std::string name = lua_tostring(L, idx);
      got = "the string '" + name + "'";
      for (const auto& m : shading::models())
        if (m->name == name) got += " (sn.lighting." + name + " {} makes that model, or sn.lighting.new(\"" + name + "\", {...}))";
    }
    throw Error(what + ": a lighting model (sn.lighting.*{...}) expected, got " + got);
  }
  return check<LightingParams>(L, idx, kLightingType);
}

Light check_light(lua_State* L, int idx, const char* what, const Light& def) {
  if (lua_isnoneornil(L, idx)) return def;
  Options o(L, idx, what, {"dir", "color"});
  glm::dvec3 dir = def.dir, color = def.color;
  if (o.has("dir")) {
    auto v = o.numbers("dir", 3);
    dir = {v[0], v[1], v[2]};
  }
  if (o.has("color")) {
    auto v = o.numbers("color", -1);
    if (v.size() == 1) v = {v[0], v[0], v[0]};
    if (v.size() != 3) throw Error(o.where("color") + ": {r, g, b} or one number expected");
    color = {v[0], v[1], v[2]};
  }
  try {
    return scene::make_light(dir, color);
  } catch (const std::exception& e) {
    throw Error(std::string(what) + ": " + e.what());
  }
}

std::vector<Light> check_lights(lua_State* L, int idx, const char* fn) {
  if (lua_isnoneornil(L, idx)) return shading::stress_lights();
  const std::string list = std::string(fn) + ": a list of lights ({ {dir = ..., color = ...}, ... }) expected as argument " +
                           std::to_string(idx);
  if (!lua_istable(L, idx)) throw Error(list + ", got " + type_name_at(L, idx));
  // A named key (a single light, or a misspelt option) would otherwise be skipped, and an empty
  // list compares nothing: both passed as a perfect match.
  const int n = check_list(L, idx, std::string(fn) + ": argument " + std::to_string(idx),
                           "a list of lights: { {dir = ..., color = ...}, ... }; a single light goes in braces too");
  if (n == 0) throw Error(list + ", got an empty list: there would be nothing to compare");
  std::vector<Light> lights;
  for (int i = 1; i <= n; ++i) {
    lua_rawgeti(L, idx, i);
    lights.push_back(check_light(L, -1, (std::string(fn) + " light").c_str()));
    lua_pop(L, 1);
  }
  return lights;
}

void push_light(lua_State* L, const Light& l) {
  lua_createtable(L, 0, 2);
  push_vec3(L, l.dir);
  lua_setfield(L, -2, "dir");
  push_vec3(L, l.color);
  lua_setfield(L, -2, "color");
}

namespace {

LightingParams& self(lua_State* L) { return check<LightingParams>(L, 1, kLightingType); }

// Reads { name = number | {numbers}, ... } into a parameter map for make_params.
std::map<std::string, std::vector<double>> read_params(lua_State* L, int idx, const char* model) {
  std::map<std::string, std::vector<double>> given;
  if (lua_isnoneornil(L, idx)) return given;
  if (!lua_istable(L, idx))
    throw Error(std::string("sn.lighting.") + model + ": parameter table expected, got " + type_name_at(L, idx));
  idx = absindex(L, idx);
  lua_pushnil(L);
  while (lua_next(L, idx)) {
    if (lua_type(L, -2) != LUA_TSTRING) {
      lua_pop(L, 2);
      throw Error(std::string("sn.lighting.") + model + ": parameters must be named (name = value)");
    }
    std::string name = lua_tostring(L, -2);
    given[name] = check_numbers(L, -1, (std::string("sn.lighting.") + model + " parameter '" + name + "'").c_str());
    lua_pop(L, 1);
  }
  return given;
}

}  // namespace

int make_lighting(lua_State* L, const shading::ModelPtr& m, int idx) {
  push(L, std::make_shared<LightingParams>(shading::make_params(m, read_params(L, idx, m->name.c_str()))), kLightingType);
  return 1;
}

namespace {

// sn.lighting.NAME{params}: the constructor __index hands out for every registered model.
int w_make(lua_State* L) {
  return make_lighting(L, shading::find_model(lua_tostring(L, lua_upvalueindex(1))), 1);
}

// sn.lighting.new(name, {params}) -- the model chosen by a string (sweeps over models).
int w_new(lua_State* L) {
  return make_lighting(L, shading::find_model(check_string(L, 1, "sn.lighting.new model name")), 2);
}

// sn.lighting.models() -> {"phong", "blinn_phong", ..., then defined models}
int w_models(lua_State* L) {
  std::vector<std::string> names;
  for (const auto& m : shading::models()) names.push_back(m->name);
  push_strings(L, names);
  return 1;
}

// sn.lighting.NAME -> the constructor of a registered model, else a clear error instead of
// "attempt to call a nil value".
int w_index(lua_State* L) {
  std::string name = lua_isstring(L, 2) ? lua_tostring(L, 2) : type_name_at(L, 2);
  for (const auto& m : shading::models())
    if (m->name == name) {
      lua_pushstring(L, name.c_str());
      lua_pushcclosure(L, wrap<w_make>, 1);
      // Kept, so sn.lighting.NAME is one function (an error can then name it when it is passed
      // uncalled); it looks the model up by name when called, so a redefinition still applies.
      lua_pushvalue(L, 2);
      lua_pushvalue(L, -2);
      lua_rawset(L, 1);
      return 1;
    }
  throw Error("unknown lighting model 'sn.lighting." + name + "' (valid: " + shading::model_names() +
              ", or sn.lighting.define{...}, sn.lighting.new(name, params), sn.lighting.models(), "
              "sn.lighting.stress, sn.lighting.check)");
}

void push_value(lua_State* L, const std::array<double, 4>& v, int n) {
  if (n == 1) {
    lua_pushnumber(L, v[0]);
    return;
  }
  lua_createtable(L, n, 0);
  for (int c = 0; c < n; ++c) {
    lua_pushnumber(L, v[c]);
    lua_rawseti(L, -2, c + 1);
  }
}

// model:params() -> { name = number | {r,g,b} | {t1..t4}, ... }
int w_params(lua_State* L) {
  const LightingParams& p = self(L);
  const auto& s = p.spec();
  lua_createtable(L, 0, int(s.params.size()));
  for (std::size_t i = 0; i < s.params.size(); ++i) {
    push_value(L, p.values[i], s.params[i].components);
    lua_setfield(L, -2, s.params[i].name.c_str());
  }
  return 1;
}

int w_name(lua_State* L) {
  lua_pushstring(L, self(L).spec().name.c_str());
  return 1;
}

// model:with{ roughness = 0.5 } -> a new model: this one's parameters with some changed.
int w_with(lua_State* L) {
  const LightingParams& p = self(L);
  const auto& s = p.spec();
  auto given = read_params(L, 2, s.name.c_str());
  for (std::size_t i = 0; i < s.params.size(); ++i)
    if (!given.count(s.params[i].name))
      given[s.params[i].name] = std::vector<double>(p.values[i].begin(), p.values[i].begin() + s.params[i].components);
  push(L, std::make_shared<LightingParams>(shading::make_params(p.model, given)), kLightingType);
  return 1;
}

// model:attributes() -> the G-buffer attributes it reads
int w_attributes(lua_State* L) {
  auto a = shading::model_attributes(self(L));
  push_strings(L, a);
  return 1;
}

glm::dvec3 vec3_option(const Options& o, const char* key, glm::dvec3 def) {
  if (!o.has(key)) return def;
  auto v = o.finite_numbers(key, 3);  // a NaN base shaded NaN, a NaN normal a plausible colour
  return {v[0], v[1], v[2]};
}

// model:shade{ normal = {x,y,z}, view = {x,y,z}, light = {dir, color}, base = {r,g,b}, uv = {u,v},
//   position, world_position, tangent, bitangent = {x,y,z}, raw = false }
//   -> {r, g, b} from the double-precision twin
int w_shade(lua_State* L) {
  const LightingParams& p = self(L);
  Options o(L, 2, "model:shade",
            {"normal", "view", "light", "base", "uv", "position", "world_position", "tangent", "bitangent", "raw"});
  int li = o.push("light");
  Light light = check_light(L, li, "model:shade option 'light'");
  lua_pop(L, 1);
  if (!o.has("normal") || !o.has("view")) throw Error("model:shade needs 'normal' and 'view'");
  // What the model reads must be given (a textured model without `base` shaded white).
  for (const std::string& a : p.spec().attributes) {
    const std::string key = a == "base_color" ? "base" : a;
    if (!o.has(key.c_str()))
      throw Error("model:shade: the model " + p.spec().name + " reads the attribute '" + a + "': give " + key + " = {...}");
  }
  shading::Surface s = shading::make_surface(light, vec3_option(o, "normal", {0, 0, 0}), vec3_option(o, "view", {0, 0, 0}));
  s.base_color = vec3_option(o, "base", glm::dvec3(1.0));
  if (o.has("uv")) {
    auto uv = o.finite_numbers("uv", 2);
    s.uv = {uv[0], uv[1]};
  }
  s.position = vec3_option(o, "position", glm::dvec3(0.0));
  s.world_position = vec3_option(o, "world_position", glm::dvec3(0.0));
  s.tangent = shading::safe_normalize(vec3_option(o, "tangent", glm::dvec3(0.0)));
  s.bitangent = shading::safe_normalize(vec3_option(o, "bitangent", glm::dvec3(0.0)));
  push_vec3(L, o.boolean("raw", false) ? shading::shade_raw(p, s) : shading::shade(p, s));
  return 1;
}

// model:evaluate{ normals = Buffer, views = Buffer, targets = Buffer, count = n, light = {...},
//                 color = "rgb", raw = false, and per attribute the model reads: base_colors, uvs,
//                 positions, world_positions, tangents, bitangents = Buffer }
// Shades `count` vec4 samples on the GPU (eval_lighting.comp) into `targets`.
int w_evaluate(lua_State* L) {
  const LightingParams& p = self(L);
  Options o(L, 2, "model:evaluate",
            {"normals", "views", "targets", "count", "light", "color", "raw", "base_colors", "uvs", "positions",
             "world_positions", "tangents", "bitangents"});
  auto buffer = [&](const char* key, bool required) -> gl::Buffer* {
    int i = o.push(key);
    gl::Buffer* b = nullptr;
    if (!lua_isnil(L, i)) b = &check<gl::Buffer>(L, i, "Buffer");
    else if (required) throw Error(o.where(key) + " is required (a vec4 Buffer)");
    lua_pop(L, 1);  // the option table keeps the buffer alive
    return b;
  };
  gl::Buffer* n = buffer("normals", true);
  shading::SampleBuffers in{{"normal", n}, {"view", buffer("views", true)}};
  for (const auto& a : p.spec().attributes) {
    std::string key = a + "s";
    in[a] = buffer(key.c_str(), false);
    if (!in[a]) throw Error("model:evaluate: lighting model " + p.spec().name + " reads '" + a + "': give " + key + " = Buffer");
  }
  gl::Buffer* out = buffer("targets", true);
  long long count = o.integer("count", (long long)n->count());
  if (count < 0) throw Error("model:evaluate option 'count' must be >= 0");
  int li = o.push("light");
  Light light = check_light(L, li, "model:evaluate option 'light'");
  lua_pop(L, 1);
  auto color = shading::parse_color_space(o.string("color", "rgb"));
  shading::evaluate(p, light, in, *out, std::size_t(count), color, o.boolean("raw", false));
  return 0;
}

// model:bound([light]) -> {r,g,b}: no raw output exceeds it
int w_bound(lua_State* L) {
  push_vec3(L, shading::upper_bound(self(L), check_light(L, 2, "model:bound light")));
  return 1;
}

int w_tostring(lua_State* L) {
  auto* ud = static_cast<Box<LightingParams>*>(test_type(L, 1, kLightingType));
  if (!ud || !ud->ptr) lua_pushstring(L, "Lighting (released)");
  else lua_pushstring(L, ud->ptr->describe().c_str());
  return 1;
}

int w_eq(lua_State* L) {
  auto* a = static_cast<Box<LightingParams>*>(test_type(L, 1, kLightingType));
  auto* b = static_cast<Box<LightingParams>*>(test_type(L, 2, kLightingType));
  // The same name and parameters, and the same definition: a name defined again with other GLSL
  // is another model (both printed alike and compared equal, though they shaded apart).
  const bool same = a && b && a->ptr && b->ptr && a->ptr->key() == b->ptr->key() &&
                    (a->ptr->model == b->ptr->model || a->ptr->spec().same_glsl(b->ptr->spec()));
  lua_pushboolean(L, same);
  return 1;
}

void push_counts(lua_State* L, const shading::StressCounts& c) {
  lua_createtable(L, 0, 4);
  lua_pushinteger(L, lua_Integer(c.nan)), lua_setfield(L, -2, "nan");
  lua_pushinteger(L, lua_Integer(c.inf)), lua_setfield(L, -2, "inf");
  lua_pushinteger(L, lua_Integer(c.negative)), lua_setfield(L, -2, "negative");
  lua_pushinteger(L, lua_Integer(c.over)), lua_setfield(L, -2, "over");
}

// sn.lighting.stress(model [, {light, ...}]) -> { samples, gpu = {nan, inf, negative, over},
//   twin = {...}, encoded_nan, encoded_out_of_range, max_raw, failures }
int w_stress(lua_State* L) {
  const LightingParams& p = check_lighting(L, 1, "sn.lighting.stress model");
  auto r = shading::stress_test(p, check_lights(L, 2, "sn.lighting.stress"));
  lua_createtable(L, 0, 8);
  lua_pushinteger(L, lua_Integer(r.samples)), lua_setfield(L, -2, "samples");
  push_counts(L, r.gpu), lua_setfield(L, -2, "gpu");
  push_counts(L, r.twin), lua_setfield(L, -2, "twin");
  lua_pushinteger(L, lua_Integer(r.encoded_nan)), lua_setfield(L, -2, "encoded_nan");
  lua_pushinteger(L, lua_Integer(r.encoded_out_of_range)), lua_setfield(L, -2, "encoded_out_of_range");
  lua_pushnumber(L, r.max_raw), lua_setfield(L, -2, "max_raw");
  lua_pushinteger(L, lua_Integer(r.failures())), lua_setfield(L, -2, "failures");
  return 1;
}

// sn.lighting.stress_cases() -> { {label = "ggx roughness=0", model = Lighting}, ... }
int w_stress_cases(lua_State* L) {
  auto cases = shading::stress_cases();
  lua_createtable(L, int(cases.size()), 0);
  for (std::size_t i = 0; i < cases.size(); ++i) {
    lua_createtable(L, 0, 2);
    lua_pushstring(L, cases[i].label.c_str());
    lua_setfield(L, -2, "label");
    push(L, std::make_shared<LightingParams>(cases[i].params), kLightingType);
    lua_setfield(L, -2, "model");
    lua_rawseti(L, -2, int(i + 1));
  }
  return 1;
}

// ---- sn.color ----

shading::ColorSpace check_space(lua_State* L, int idx) {
  return shading::parse_color_space(check_string(L, idx, "colour space"));
}

glm::dvec3 check_vec3(lua_State* L, int idx, const char* what) {
  auto v = check_numbers(L, idx, what, 3);
  for (int c = 0; c < 3; ++c)  // HSV of a NaN red came out {0, 0, nan}, an infinite one decoded as is
    if (!std::isfinite(v[c]))
      throw Error(std::string(what) + ": component " + std::to_string(c + 1) + " is " + io::number_text(v[c]) +
                  "; colours must be finite");
  return {v[0], v[1], v[2]};
}

// sn.color.encode(space, {r,g,b}) -> the colour in `space`; sn.color.decode(space, c) -> {r,g,b}
int w_encode(lua_State* L) {
  push_vec3(L, shading::encode_color(check_space(L, 1), check_vec3(L, 2, "sn.color.encode colour")));
  return 1;
}
int w_decode(lua_State* L) {
  push_vec3(L, shading::decode_color(check_space(L, 1), check_vec3(L, 2, "sn.color.decode colour")));
  return 1;
}

// sn.color.convert{ input = Buffer, output = Buffer, space = "hsv", to_rgb = false, count = n } (GPU)
int w_convert(lua_State* L) {
  Options o(L, 1, "sn.color.convert", {"input", "output", "space", "to_rgb", "count"});
  int i = o.push("input");
  auto& in = check<gl::Buffer>(L, i, "Buffer");
  int j = o.push("output");
  auto& out = check<gl::Buffer>(L, j, "Buffer");
  lua_pop(L, 2);
  auto space = shading::parse_color_space(o.string("space"));
  long long count = o.integer("count", (long long)in.count());
  if (count < 0) throw Error("sn.color.convert option 'count' must be >= 0");
  shading::convert_colors(in, out, std::size_t(count), space, o.boolean("to_rgb", false));
  return 0;
}

// sn.lighting.key(name) -> a user definition's key, nil for a built-in: its GLSL as the shaders
// read it (every #included file's text in place, as it was defined) and the attributes it reads, so a sweep trains
// again when an included file or the attributes change (the main file's text alone kept runs
// of the old model).
int w_key(lua_State* L) {
  const shading::ModelPtr m = shading::find_model(check_string(L, 1, "sn.lighting.key name"));
  if (m->builtin) {
    push_definition_key(L, {});
    return 1;
  }
  const gl::Includes includes = shading::lighting_includes(*m);
  const std::string glsl = gl::preprocess_text("lighting/model.glsl", includes.at("lighting/model.glsl"), {}, includes).text;
  push_definition_key(L, {glsl, "attributes " + io::join(m->attributes)});
  return 1;
}

const luaL_Reg kLightingFns[] = {
    SN_FN("define", w_define),
    SN_FN("key", w_key),
    SN_FN("check", w_check),
    SN_FN("new", w_new),
    SN_FN("models", w_models),
    SN_FN("stress", w_stress),
    SN_FN("stress_cases", w_stress_cases),
    {nullptr, nullptr}};

}  // namespace

bool lighting_function_name(const std::string& name) {
  for (const luaL_Reg* f = kLightingFns; f->name; ++f)
    if (name == f->name) return true;
  return false;
}

void open_lighting(lua_State* L) {
  static const luaL_Reg methods[] = {SN_FN("params", w_params),     SN_FN("name", w_name),
                                     SN_FN("with", w_with),         SN_FN("attributes", w_attributes),
                                     SN_FN("shade", w_shade),       SN_FN("evaluate", w_evaluate),
                                     SN_FN("bound", w_bound),       {nullptr, nullptr}};
  static const luaL_Reg meta[] = {{"__eq", w_eq}, {nullptr, nullptr}};
  define_box_type<LightingParams>(L, kLightingType, methods, wrap<w_tostring>, meta);

  lua_newtable(L);
  luaL_register(L, nullptr, kLightingFns);
  lua_newtable(L);  // metatable: sn.lighting.NAME is a registered model's constructor, else an error
  lua_pushcfunction(L, wrap<w_index>);
  lua_setfield(L, -2, "__index");
  lua_setmetatable(L, -2);
  lua_setfield(L, -2, "lighting");

  static const luaL_Reg color_fns[] = {SN_FN("encode", w_encode), SN_FN("decode", w_decode),
                                       SN_FN("convert", w_convert), {nullptr, nullptr}};
  lua_newtable(L);
  luaL_register(L, nullptr, color_fns);
  lua_setfield(L, -2, "color");
}

}  // namespace sn::lua

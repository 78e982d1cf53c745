// sn.scene{...}: meshes, cameras, an image size and a light; scene:gbuffer{...} ("GBuffer"),
// scene:dataset{...} (a cached "Dataset"), sn.render_truth(gbuffer, model, light) and the
// dataset cache counters. scene:render lives in shadenet.scene.lua.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "data/dataset_cache.h"
#include "io/text.h"
#include "lua/binding.h"
#include "lua/lighting_binding.h"
#include "lua/lua_scene.h"
#include "lua/module.h"
#include "scene/gather.h"
#include "scene/gbuffer.h"
#include "scene/gltf.h"
#include "scene/scene.h"
#include "scene/transform.h"
#include "shading/render_truth.h"

namespace sn::lua {

namespace {

constexpr const char* kType = kSceneType;
constexpr const char* kGBufferType = "GBuffer";

LuaScene& self(lua_State* L) { return check<LuaScene>(L, 1, kType); }

std::shared_ptr<scene::Mesh> mesh_at(lua_State* L, int idx, LuaScene& s) {
  if (lua_type(L, idx) == LUA_TSTRING) {
    std::string path = lua_tostring(L, idx);
    auto m = std::make_shared<scene::Mesh>(scene::load_mesh(path));
    for (const std::string& n : m->notes) {
      std::string note = "mesh file '" + path + "' " + n;
      fprintf(stderr, "note: %s\n", note.c_str());
      s.notes.push_back(note);
    }
    return m;
  }
  if (test_type(L, idx, "Mesh")) {
    auto m = check_shared<scene::Mesh>(L, idx, "Mesh");
    if (m->normals_computed) s.notes.push_back("mesh '" + m->name + "' had no normals; they were computed");
    return m;
  }
  throw Error("sn.scene option 'mesh': a file path, a Mesh or a list of them expected, got " + type_name_at(L, idx));
}

std::vector<std::string> string_list(lua_State* L, int idx, const std::string& what) {
  if (!lua_istable(L, idx)) throw Error(what + ": list of names expected, got " + type_name_at(L, idx));
  std::vector<std::string> v;
  const int n = check_list(L, idx, what);
  for (int i = 1; i <= n; ++i) {
    lua_rawgeti(L, idx, i);
    v.push_back(check_string(L, -1, (what + " element " + std::to_string(i)).c_str()));
    lua_pop(L, 1);
  }
  return v;
}

// One ring of framing cameras: { count = 8, elevation = 20, distance = ..., fov = 45 }.
std::vector<scene::Camera> read_ring(lua_State* L, int idx, const std::string& what, const scene::Bounds& b) {
  Options o(L, idx, what.c_str(), {"count", "elevation", "distance", "fov"});
  const long long count = o.integer("count", 8);
  if (count < 1 || count > 4096)
    throw Error(o.where("count") + ": a view ring needs 1..4096 cameras, got " + std::to_string(count));
  // Checked here, by name: a NaN distance was reported as a camera standing "nan" from the meshes.
  std::optional<double> distance;
  if (o.has("distance")) {
    distance = o.number("distance");
    if (!(*distance > 0 && *distance <= 1e38))
      throw Error(o.where("distance") + " must be a number in (0, 1e38], got " + io::number_text(*distance));
  }
  const double elevation = o.number("elevation", 20);
  check_finite({elevation}, o.where("elevation"));
  return scene::framing_orbit(b, int(count), elevation, o.number("fov", 45), distance);
}

// views = { count = 8, elevation = 20, ... } (one ring framing the meshes in every pose), or a
// list whose elements are Cameras or rings: { {count = 8, elevation = -30}, {count = 8, elevation = 70} }
std::vector<scene::Camera> read_views(lua_State* L, int idx, const scene::Bounds& b) {
  if (lua_isnil(L, idx)) return scene::framing_orbit(b);
  if (!lua_istable(L, idx)) throw Error("sn.scene option 'views': a list of cameras and view rings, or one ring expected");
  if (lua_objlen(L, idx) == 0) return read_ring(L, idx, "sn.scene option 'views'", b);
  const int n = check_list(L, idx, "sn.scene option 'views'", "cameras and rings, each in braces: { {count = 8}, camera }");
  std::vector<scene::Camera> cams;
  for (int i = 1; i <= n; ++i) {
    lua_rawgeti(L, idx, i);
    const std::string what = "sn.scene option 'views' element " + std::to_string(i);
    if (test_type(L, -1, "Camera")) {
      cams.push_back(check<scene::Camera>(L, -1, "Camera"));
    } else if (lua_istable(L, -1)) {
      for (auto& c : read_ring(L, lua_gettop(L), what + " (a view ring)", b)) cams.push_back(c);
    } else {
      throw Error(what + ": a Camera or a view ring { count = 8, elevation = 20 } expected, got " + type_name_at(L, -1));
    }
    lua_pop(L, 1);
  }
  return cams;
}

// Within a float's range: the shaders hold the transformed meshes in floats (a translate of 1e300
// was reported as a camera standing 4.07 from the meshes, "where float runs out").
glm::dvec3 vec3_option(const Options& o, const char* key) {
  auto v = o.finite_numbers(key, 3, true);
  return {v[0], v[1], v[2]};
}

// A transform: 4 rows of 4 numbers, 16 numbers row by row, or terms
// { rotate = {degrees, x, y, z}, scale = s | {sx, sy, sz}, translate = {x, y, z}, about = {x, y, z} }.
glm::dmat4 read_transform(lua_State* L, int idx, const std::string& what, const glm::dvec3& default_about) {
  const std::string expected = ": a 4x4 transform (4 rows of 4 numbers, or 16 numbers row by row) or "
                               "{ rotate = {degrees, x, y, z}, scale = ..., translate = {x, y, z}, about = {x, y, z} } expected";
  if (!lua_istable(L, idx)) throw Error(what + expected + ", got " + type_name_at(L, idx));
  if (lua_objlen(L, idx) == 0) {
    Options o(L, idx, what.c_str(), {"rotate", "scale", "translate", "about"});
    scene::TransformTerms t;
    if (o.has("rotate")) {
      auto r = o.numbers("rotate", 4);
      t.degrees = r[0], t.axis = {r[1], r[2], r[3]};
    }
    if (o.has("scale")) {
      int si = o.push("scale");
      if (lua_type(L, si) == LUA_TNUMBER) {
        const double k = lua_tonumber(L, si);
        check_finite({k}, o.where("scale"), true);
        t.scale = {k, k, k};
      } else {
        t.scale = vec3_option(o, "scale");
      }
      lua_pop(L, 1);
    }
    if (o.has("translate")) t.translate = vec3_option(o, "translate");
    if (o.has("about")) t.about = vec3_option(o, "about");
    try {
      return scene::make_transform(t, default_about, what);
    } catch (const std::invalid_argument& e) {
      throw Error(e.what());
    }
  }
  const int n = check_list(L, idx, what);
  std::vector<double> v;
  if (n == 16) {
    v = check_numbers(L, idx, what.c_str(), 16);
    check_finite(v, what, true);
  } else if (n == 4) {
    for (int r = 1; r <= 4; ++r) {
      lua_rawgeti(L, idx, r);
      if (!lua_istable(L, -1)) throw Error(what + expected + " (row " + std::to_string(r) + " is " + type_name_at(L, -1) + ")");
      auto row = check_numbers(L, -1, (what + " row " + std::to_string(r)).c_str(), 4);
      check_finite(row, what + " row " + std::to_string(r), true);
      v.insert(v.end(), row.begin(), row.end());
      lua_pop(L, 1);
    }
  } else {
    throw Error(what + expected + " (it has " + std::to_string(n) + " elements)");
  }
  glm::dmat4 m;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m[c][r] = v[size_t(r * 4 + c)];  // glm is column-major
  try {
    scene::check_transform(m, what);
  } catch (const std::invalid_argument& e) {
    throw Error(e.what());
  }
  return m;
}

// meshes = { "a.glb", Mesh, { mesh = "b.glb", transform = ... }, ... }
void read_meshes(lua_State* L, int idx, LuaScene& s) {
  const int n = lua_istable(L, idx) ? check_list(L, idx, "sn.scene option 'meshes'") : 0;
  if (n == 0) throw Error("sn.scene option 'meshes': a non-empty list of meshes or { mesh = ..., transform = ... } expected");
  for (int i = 1; i <= n; ++i) {
    lua_rawgeti(L, idx, i);
    const int e = lua_gettop(L);
    const std::string what = "sn.scene option 'meshes' element " + std::to_string(i);
    if (lua_istable(L, e)) {
      Options o(L, e, what.c_str(), {"mesh", "transform"});
      int m = o.push("mesh");
      if (lua_isnil(L, m)) throw Error(what + ": 'mesh' is required (a path or a Mesh)");
      scene::PlacedMesh placed{mesh_at(L, m, s)};
      lua_pop(L, 1);
      if (o.has("transform")) {
        int t = o.push("transform");
        placed.transform = read_transform(L, t, what + " transform", placed.mesh->bounds.center());
        lua_pop(L, 1);
      }
      s.scene.meshes.push_back(std::move(placed));
    } else {
      s.scene.meshes.push_back({mesh_at(L, e, s)});
    }
    lua_pop(L, 1);
  }
}

// sn.scene{ mesh = path | Mesh | {...} or meshes = {...}, poses = {...}, size = {w, h}, views = ...,
//           light = {dir, color} }
int w_new(lua_State* L) {
  Options o(L, 1, "sn.scene", {"mesh", "meshes", "poses", "size", "views", "light"});
  auto s = std::make_shared<LuaScene>();
  if (o.has("mesh") && o.has("meshes")) throw Error("sn.scene: give 'mesh' or 'meshes', not both");
  if (o.has("meshes")) {
    int mi = o.push("meshes");
    read_meshes(L, mi, *s);
    lua_pop(L, 1);
  } else {
    int mi = o.push("mesh");
    if (lua_isnil(L, mi)) throw Error("sn.scene option 'mesh' is required (a path, a Mesh, or a list of them)");
    if (lua_istable(L, mi)) {
      const int n = check_list(L, mi, "sn.scene option 'mesh'");
      if (n == 0) throw Error("sn.scene option 'mesh': the list is empty");
      for (int i = 1; i <= n; ++i) {
        lua_rawgeti(L, mi, i);
        s->scene.meshes.push_back({mesh_at(L, lua_gettop(L), *s)});
        lua_pop(L, 1);
      }
    } else {
      s->scene.meshes.push_back({mesh_at(L, mi, *s)});
    }
    lua_pop(L, 1);
  }
  if (o.has("poses")) {
    int pi = o.push("poses");
    const int n = lua_istable(L, pi) ? check_list(L, pi, "sn.scene option 'poses'") : 0;
    if (n == 0) throw Error("sn.scene option 'poses': a non-empty list of transforms expected");
    const glm::dvec3 centre = s->scene.placed_bounds().center();
    s->scene.poses.clear();
    for (int i = 1; i <= n; ++i) {
      lua_rawgeti(L, pi, i);
      s->scene.poses.push_back(read_transform(L, lua_gettop(L), "sn.scene option 'poses' element " + std::to_string(i), centre));
      lua_pop(L, 1);
    }
    lua_pop(L, 1);
  }
  if (o.has("size")) {
    auto v = o.numbers("size", 2);
    if (v[0] < 1 || v[1] < 1 || v[0] > 16384 || v[1] > 16384 || v[0] != std::floor(v[0]) || v[1] != std::floor(v[1]))
      throw Error("sn.scene option 'size': two whole numbers in 1..16384 expected");
    s->scene.width = int(v[0]), s->scene.height = int(v[1]);
  }
  int vi = o.push("views");
  s->scene.views = read_views(L, vi, s->scene.bounds());
  lua_pop(L, 1);
  int li = o.push("light");
  s->scene.light = check_light(L, li, "sn.scene option 'light'");
  lua_pop(L, 1);
  push(L, std::move(s), kType);
  return 1;
}

int pose_index(const Options& o, const LuaScene& s) {
  long long p = o.integer("pose", 1);
  if (p < 1 || p > (long long)s.scene.poses.size())
    throw Error(o.where("pose") + ": " + std::to_string(p) + " is outside the scene's poses 1.." +
                std::to_string(s.scene.poses.size()));
  return int(p - 1);
}

int view_index(const Options& o, const LuaScene& s) {
  long long v = o.integer("view", 1);
  if (v < 1 || v > (long long)s.scene.views.size())
    throw Error(o.where("view") + ": " + std::to_string(v) + " is outside the scene's views 1.." +
                std::to_string(s.scene.views.size()));
  return int(v - 1);
}

// scene:gbuffer{ view = 1, pose = 1, attributes = {"normal", "view"}, camera = Camera (instead of a
//                view: live mode's orbit), size = {w, h} (default: the scene's) } -> GBuffer
int w_gbuffer(lua_State* L) {
  LuaScene& s = self(L);
  Options o(L, 2, "scene:gbuffer", {"view", "pose", "attributes", "camera", "size"});
  if (o.has("view") && o.has("camera")) throw Error("scene:gbuffer: give 'view' or 'camera', not both");
  int view = view_index(o, s);
  int pose = pose_index(o, s);
  std::vector<std::string> attributes = {"normal", "view"};
  if (o.has("attributes")) {
    int a = o.push("attributes");
    attributes = string_list(L, a, o.where("attributes"));
    lua_pop(L, 1);
  }
  int w = s.scene.width, h = s.scene.height;
  if (o.has("size")) {
    auto v = o.numbers("size", 2);
    if (v[0] < 1 || v[1] < 1 || v[0] > 16384 || v[1] > 16384 || v[0] != std::floor(v[0]) || v[1] != std::floor(v[1]))
      throw Error(o.where("size") + ": two whole numbers in 1..16384 expected");
    w = int(v[0]), h = int(v[1]);
  }
  const scene::Camera* camera = &s.scene.views[size_t(view)];
  if (o.has("camera")) {
    int c = o.push("camera");
    if (!test_type(L, c, "Camera")) throw Error(o.where("camera") + ": Camera expected, got " + type_name_at(L, c));
    camera = &check<scene::Camera>(L, c, "Camera");  // stays on the stack, alive, until we return
  }
  push(L, std::make_shared<scene::GBuffer>(scene::render_gbuffer(s.scene.draws(pose), *camera, w, h, attributes)),
       kGBufferType);
  return 1;
}

// scene:dataset{ inputs = {"normal", "view"}, target = model, color = "rgb", views = {1, 2, ...},
//                poses = {1, 2, ...}, split = 0.8, seed = 1, samples = 64149 | "all",
//                vary = { param = {min, max}, ... } } -> Dataset (cached)
int w_dataset(lua_State* L) {
  LuaScene& s = self(L);
  Options o(L, 2, "scene:dataset", {"inputs", "target", "color", "views", "poses", "split", "seed", "samples", "vary"});
  data::DatasetRequest r;
  int t = o.push("target");
  if (lua_isnil(L, t)) throw Error("scene:dataset option 'target' is required (a lighting model, e.g. sn.lighting.phong{})");
  r.target = check_lighting(L, t, o.where("target"));
  lua_pop(L, 1);
  if (o.has("inputs")) {
    int a = o.push("inputs");
    r.inputs = string_list(L, a, o.where("inputs"));
    lua_pop(L, 1);
  }
  r.color = shading::parse_color_space(o.string("color", "rgb"));
  // 1-based indices from Lua -> 0-based, each within 1..count and listed once (a repeated view
  // would put the same rows in training and validation both).
  auto indices = [&](const char* key, std::size_t count, const char* noun) {
    std::vector<int> out;
    int v = o.push(key);
    auto list = check_numbers(L, v, o.where(key).c_str());
    lua_pop(L, 1);
    if (list.empty())
      throw Error(o.where(key) + ": an empty list selects no " + noun + "; leave it out for all " +
                  std::to_string(count) + " of them");
    std::vector<bool> seen(count);
    for (double x : list) {
      if (x < 1 || x > double(count) || x != std::floor(x))
        throw Error(o.where(key) + ": " + noun + " " + io::number_text(x) + " is outside the scene's " + noun + "s 1.." +
                    std::to_string(count));
      if (seen[std::size_t(x) - 1])
        throw Error(o.where(key) + ": " + noun + " " + io::number_text(x) + " is listed twice");
      seen[std::size_t(x) - 1] = true;
      out.push_back(int(x) - 1);
    }
    return out;
  };
  if (o.has("views")) r.views = indices("views", s.scene.views.size(), "view");
  if (o.has("poses")) r.poses = indices("poses", s.scene.poses.size(), "pose");
  r.split = o.number("split", 0.8);
  r.seed = o.seed("seed", 1);
  int si = o.push("samples");
  if (lua_type(L, si) == LUA_TSTRING) {
    if (std::string(lua_tostring(L, si)) != "all")
      throw Error(o.where("samples") + ": a positive count or \"all\" expected, got '" + lua_tostring(L, si) + "'");
    r.samples = 0;
  } else if (!lua_isnil(L, si)) {
    long long n = check_integer(L, si, o.where("samples").c_str());
    if (n < 2) throw Error(o.where("samples") + " must be at least 2 (one training and one validation row), got " +
                           std::to_string(n));
    r.samples = std::size_t(n);
  }
  lua_pop(L, 1);
  if (o.has("vary")) {
    int vi = o.push("vary");
    if (!lua_istable(L, vi)) throw Error(o.where("vary") + ": { parameter = {min, max}, ... } expected");
    lua_pushnil(L);
    while (lua_next(L, vi)) {
      if (lua_type(L, -2) != LUA_TSTRING) throw Error(o.where("vary") + ": keys must be parameter names");
      std::string name = lua_tostring(L, -2);
      auto range = check_numbers(L, -1, (o.where("vary") + " '" + name + "'").c_str(), 2);
      r.vary.push_back({name, range[0], range[1]});
      lua_pop(L, 1);
    }
    lua_pop(L, 1);
    // Lua tables have no order; the vec4 of varied values is laid out by name.
    std::sort(r.vary.begin(), r.vary.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  }
  push(L, data::cached_dataset(s.scene, r), "Dataset");
  return 1;
}

int w_views(lua_State* L) {
  LuaScene& s = self(L);
  lua_createtable(L, int(s.scene.views.size()), 0);
  for (std::size_t i = 0; i < s.scene.views.size(); ++i) {
    push(L, std::make_shared<scene::Camera>(s.scene.views[i]), "Camera");
    lua_rawseti(L, -2, int(i + 1));
  }
  return 1;
}

// scene:poses() -> { {4 rows of 4 numbers}, ... }
int w_poses(lua_State* L) {
  LuaScene& s = self(L);
  lua_createtable(L, int(s.scene.poses.size()), 0);
  for (std::size_t i = 0; i < s.scene.poses.size(); ++i) {
    lua_createtable(L, 4, 0);
    for (int r = 0; r < 4; ++r) {
      lua_createtable(L, 4, 0);
      for (int c = 0; c < 4; ++c) {
        lua_pushnumber(L, s.scene.poses[i][c][r]);
        lua_rawseti(L, -2, c + 1);
      }
      lua_rawseti(L, -2, r + 1);
    }
    lua_rawseti(L, -2, int(i + 1));
  }
  return 1;
}

int w_light(lua_State* L) {
  push_light(L, self(L).scene.light);
  return 1;
}

// scene:set_light{ dir = {...}, color = {...} } (what is left out stays)
int w_set_light(lua_State* L) {
  LuaScene& s = self(L);
  s.scene.light = check_light(L, 2, "scene:set_light", s.scene.light);
  return 0;
}

int w_size(lua_State* L) {
  LuaScene& s = self(L);
  lua_pushinteger(L, s.scene.width), lua_pushinteger(L, s.scene.height);
  return 2;
}

int w_bounds(lua_State* L) {
  auto b = self(L).scene.bounds();
  push_vec3(L, b.min);
  push_vec3(L, b.max);
  return 2;
}

int w_meshes(lua_State* L) {
  LuaScene& s = self(L);
  lua_createtable(L, int(s.scene.meshes.size()), 0);
  for (std::size_t i = 0; i < s.scene.meshes.size(); ++i) {
    push(L, s.scene.meshes[i].mesh, "Mesh");
    lua_rawseti(L, -2, int(i + 1));
  }
  return 1;
}

int w_notes(lua_State* L) {
  LuaScene& s = self(L);
  push_strings(L, s.notes);
  return 1;
}

int w_tostring(lua_State* L) {
  auto* ud = static_cast<Box<LuaScene>*>(test_type(L, 1, kType));
  if (!ud || !ud->ptr) {
    lua_pushstring(L, "Scene (released)");
    return 1;
  }
  const auto& s = ud->ptr->scene;
  std::string names;
  for (const auto& m : s.meshes) names += (names.empty() ? "" : ", ") + m.mesh->name;
  const std::string poses = s.poses.size() > 1 ? " x " + std::to_string(s.poses.size()) + " poses" : "";
  lua_pushfstring(L, "Scene(%s; %d views%s of %dx%d)", names.c_str(), int(s.views.size()), poses.c_str(), s.width,
                  s.height);
  return 1;
}

// ---- GBuffer ----

scene::GBuffer& gbuffer(lua_State* L, int idx = 1) { return check<scene::GBuffer>(L, idx, kGBufferType); }

// gbuffer:read(name) -> Image (RGBA float: value in .xyz / uv in .xy, coverage in alpha)
int w_gb_read(lua_State* L) {
  scene::GBuffer& g = gbuffer(L);
  int a = g.attachment(check_string(L, 2, "gbuffer:read attribute"));
  push(L, std::make_shared<io::Image>(g.target->read(a)), "Image");
  return 1;
}

int w_gb_attributes(lua_State* L) {
  scene::GBuffer& g = gbuffer(L);
  push_strings(L, g.attributes);
  return 1;
}

int w_gb_size(lua_State* L) {
  scene::GBuffer& g = gbuffer(L);
  lua_pushinteger(L, g.width), lua_pushinteger(L, g.height);
  return 2;
}

// gbuffer:target() -> the Target holding one attachment per attribute (for textures = {...})
int w_gb_target(lua_State* L) {
  push(L, gbuffer(L).target, "Target");
  return 1;
}

// gbuffer:covered() -> number of covered pixels (gathered on the GPU)
int w_gb_covered(lua_State* L) {
  lua_pushinteger(L, lua_Integer(scene::gather(gbuffer(L)).count));
  return 1;
}

int w_gb_tostring(lua_State* L) {
  auto* ud = static_cast<Box<scene::GBuffer>*>(test_type(L, 1, kGBufferType));
  if (!ud || !ud->ptr) {
    lua_pushstring(L, "GBuffer (released)");
    return 1;
  }
  std::string a;
  for (const auto& s : ud->ptr->attributes) a += (a.empty() ? "" : ", ") + s;
  lua_pushfstring(L, "GBuffer(%dx%d: %s)", ud->ptr->width, ud->ptr->height, a.c_str());
  return 1;
}

// sn.render_truth(gbuffer, model [, light]) -> Image (RGBA, alpha = coverage)
int w_render_truth(lua_State* L) {
  scene::GBuffer& g = gbuffer(L, 1);
  auto& model = check_lighting(L, 2, "sn.render_truth model");
  scene::Light light = check_light(L, 3, "sn.render_truth light");
  push(L, std::make_shared<io::Image>(shading::render_truth(g, model, light)), "Image");
  return 1;
}

// A flat Lua array of numbers as float vectors of `width` components.
template <class V>
std::vector<V> flat_vectors(lua_State* L, const Options& o, const char* key, int width) {
  auto v = o.numbers(key, -1);
  if (v.size() % std::size_t(width))
    throw Error(o.where(key) + ": " + std::to_string(v.size()) + " numbers are not whole groups of " +
                std::to_string(width));
  std::vector<V> out(v.size() / width);
  for (std::size_t i = 0; i < out.size(); ++i)
    for (int c = 0; c < width; ++c) out[i][c] = float(v[i * width + c]);
  (void)L;
  return out;
}

// sn.procedural_mesh{ positions = {x1,y1,z1, x2,...}, normals = {...} (computed when left out),
//                     uvs = {u1,v1, ...}, indices = {i1,i2,i3, ...} (1-based, counter-clockwise
//                     seen from outside), texture = Image (base colour), name = "cloth" } -> Mesh
// For generators written in Lua (meshes/make_meshes.lua); mesh:save(path) writes the .glb.
int w_procedural_mesh(lua_State* L) {
  Options o(L, 1, "sn.procedural_mesh", {"positions", "normals", "uvs", "indices", "texture", "name"});
  scene::Mesh m;
  m.name = o.string("name", "procedural");
  m.positions = flat_vectors<glm::vec3>(L, o, "positions", 3);
  if (m.positions.empty()) throw Error("sn.procedural_mesh option 'positions' is required (x, y, z per vertex)");
  auto idx = o.numbers("indices", -1);
  if (idx.empty() || idx.size() % 3)
    throw Error("sn.procedural_mesh option 'indices': three 1-based vertex indices per triangle expected, got " +
                std::to_string(idx.size()) + " numbers");
  for (std::size_t i = 0; i < idx.size(); ++i) {
    if (idx[i] < 1 || idx[i] > double(m.positions.size()) || idx[i] != std::floor(idx[i]))
      throw Error("sn.procedural_mesh option 'indices' element " + std::to_string(i + 1) + ": " +
                  std::to_string(idx[i]) + " is not a vertex index 1.." + std::to_string(m.positions.size()));
    m.indices.push_back(uint32_t(idx[i]) - 1);
  }
  if (o.has("normals")) {
    m.normals = flat_vectors<glm::vec3>(L, o, "normals", 3);
    for (auto& n : m.normals) {
      float len = glm::length(n);
      if (!(len > 0)) throw Error("sn.procedural_mesh option 'normals': a normal is zero or not a number");
      n /= len;
    }
  } else {
    m.normals = scene::area_weighted_normals(m.positions, m.indices);
    m.normals_computed = true;
  }
  m.has_normals = true;
  if (o.has("uvs")) {
    m.uvs = flat_vectors<glm::vec2>(L, o, "uvs", 2);
    m.has_uvs = true;
  } else {
    m.uvs.assign(m.positions.size(), glm::vec2(0.0f));
  }
  if (o.has("texture")) {
    if (!m.has_uvs) throw Error("sn.procedural_mesh option 'texture' needs 'uvs' to map it");
    int t = o.push("texture");
    m.base_color = check<io::Image>(L, t, "Image");
    lua_pop(L, 1);
  }
  m.bounds = scene::compute_bounds(m.positions);
  scene::validate(m);
  push(L, std::make_shared<scene::Mesh>(std::move(m)), "Mesh");
  return 1;
}

// sn.dataset_stats() -> { builds, hits, gbuffer_renders, cached }
int w_dataset_stats(lua_State* L) {
  auto s = data::dataset_stats();
  lua_createtable(L, 0, 4);
  lua_pushinteger(L, lua_Integer(s.builds)), lua_setfield(L, -2, "builds");
  lua_pushinteger(L, lua_Integer(s.hits)), lua_setfield(L, -2, "hits");
  lua_pushinteger(L, lua_Integer(s.gbuffer_renders)), lua_setfield(L, -2, "gbuffer_renders");
  lua_pushinteger(L, lua_Integer(s.cached)), lua_setfield(L, -2, "cached");
  lua_pushinteger(L, lua_Integer(data::last_covered_pixels())), lua_setfield(L, -2, "last_covered");
  return 1;
}

int w_dataset_cache_clear(lua_State*) {
  data::clear_dataset_cache();
  return 0;
}

}  // namespace

void open_scene(lua_State* L) {
  static const luaL_Reg methods[] = {SN_FN("gbuffer", w_gbuffer), SN_FN("dataset", w_dataset),
                                     SN_FN("views", w_views),     SN_FN("poses", w_poses),
                                     SN_FN("light", w_light),
                                     SN_FN("set_light", w_set_light), SN_FN("size", w_size),
                                     SN_FN("bounds", w_bounds),   SN_FN("meshes", w_meshes),
                                     SN_FN("notes", w_notes),     {nullptr, nullptr}};
  define_box_type<LuaScene>(L, kType, methods, wrap<w_tostring>);
  static const luaL_Reg gb_methods[] = {SN_FN("read", w_gb_read),       SN_FN("attributes", w_gb_attributes),
                                        SN_FN("size", w_gb_size),       SN_FN("target", w_gb_target),
                                        SN_FN("covered", w_gb_covered), {nullptr, nullptr}};
  define_box_type<scene::GBuffer>(L, kGBufferType, gb_methods, wrap<w_gb_tostring>);
  static const luaL_Reg fns[] = {SN_FN("scene", w_new), SN_FN("render_truth", w_render_truth),
                                 SN_FN("dataset_stats", w_dataset_stats),
                                 SN_FN("dataset_cache_clear", w_dataset_cache_clear),
                                 SN_FN("procedural_mesh", w_procedural_mesh), {nullptr, nullptr}};
  luaL_register(L, nullptr, fns);
}

}  // namespace sn::lua

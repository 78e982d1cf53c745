// sn.mesh.*: glTF meshes and procedural shapes, as Mesh objects.
#include <cstdio>
#include <filesystem>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "data/dataset_cache.h"
#include "io/hash.h"
#include "lua/binding.h"
#include "lua/module.h"
#include "scene/gltf.h"
#include "scene/mesh.h"
#include "scene/procedural.h"

namespace sn::lua {

namespace {

constexpr const char* kType = "Mesh";
using scene::Mesh;

Mesh& self(lua_State* L) { return check<Mesh>(L, 1, kType); }

void push_mesh(lua_State* L, Mesh m) { push(L, std::make_shared<Mesh>(std::move(m)), kType); }

void push_vec3(lua_State* L, const glm::dvec3& v) {
  lua_createtable(L, 3, 0);
  for (int i = 0; i < 3; ++i) {
    lua_pushnumber(L, v[i]);
    lua_rawseti(L, -2, i + 1);
  }
}

// sn.mesh.load(path) -> Mesh
int w_load(lua_State* L) {
  std::string path = check_string(L, 1, "sn.mesh.load path");
  Mesh m = scene::load_mesh(path);
  for (const std::string& note : m.notes) fprintf(stderr, "note: mesh file '%s' %s\n", path.c_str(), note.c_str());
  push_mesh(L, std::move(m));
  return 1;
}

// Options are optional for the procedural shapes: sn.mesh.sphere() is the unit sphere.
bool has_options(lua_State* L) { return !lua_isnoneornil(L, 1); }

// sn.mesh.sphere{ radius = 1, segments = 64, rings = 32 }
int w_sphere(lua_State* L) {
  if (!has_options(L)) return push_mesh(L, scene::sphere()), 1;
  Options o(L, 1, "sn.mesh.sphere", {"radius", "segments", "rings"});
  push_mesh(L, scene::sphere(o.number("radius", 1), o.int32("segments", 64), o.int32("rings", 32)));
  return 1;
}

// sn.mesh.torus{ major = 1, minor = 0.25, segments = 64, sides = 32 }
int w_torus(lua_State* L) {
  if (!has_options(L)) return push_mesh(L, scene::torus()), 1;
  Options o(L, 1, "sn.mesh.torus", {"major", "minor", "segments", "sides"});
  push_mesh(L, scene::torus(o.number("major", 1), o.number("minor", 0.25), o.int32("segments", 64),
                            o.int32("sides", 32)));
  return 1;
}

// sn.mesh.plane{ size = 2, subdivisions = 1 }
int w_plane(lua_State* L) {
  if (!has_options(L)) return push_mesh(L, scene::plane()), 1;
  Options o(L, 1, "sn.mesh.plane", {"size", "subdivisions"});
  push_mesh(L, scene::plane(o.number("size", 2), o.int32("subdivisions", 1)));
  return 1;
}

// mesh:counts() -> vertices, indices
int w_counts(lua_State* L) {
  Mesh& m = self(L);
  lua_pushinteger(L, lua_Integer(m.positions.size()));
  lua_pushinteger(L, lua_Integer(m.indices.size()));
  return 2;
}

// mesh:has("normal" | "uv" | "texture") -> boolean
int w_has(lua_State* L) {
  Mesh& m = self(L);
  int what = check_choice(check_string(L, 2, "mesh:has attribute"), {"normal", "uv", "texture"}, "mesh attribute");
  lua_pushboolean(L, what == 0 ? m.has_normals : what == 1 ? m.has_uvs : m.base_color.has_value());
  return 1;
}

int w_normals_computed(lua_State* L) {
  lua_pushboolean(L, self(L).normals_computed);
  return 1;
}

// mesh:bounds() -> {xmin, ymin, zmin}, {xmax, ymax, zmax}
int w_bounds(lua_State* L) {
  Mesh& m = self(L);
  push_vec3(L, m.bounds.min);
  push_vec3(L, m.bounds.max);
  return 2;
}

// mesh:texture() -> Image (RGBA or as stored) or nil
int w_texture(lua_State* L) {
  Mesh& m = self(L);
  if (!m.base_color) return lua_pushnil(L), 1;
  push(L, std::make_shared<io::Image>(*m.base_color), "Image");
  return 1;
}

int w_name(lua_State* L) {
  lua_pushstring(L, self(L).name.c_str());
  return 1;
}

// mesh:key() -> 16 hex digits hashing what the mesh holds (positions, normals, uvs, indices,
// tangents, texture and sampler): the dataset cache's key for it, so an experiment's records can
// tell a mesh file rewritten under the same path from the one they were trained on.
int w_key(lua_State* L) {
  lua_pushstring(L, io::hex64(data::mesh_content_hash(self(L))).c_str());
  return 1;
}

// mesh:save(path) writes a .glb; returns the path
int w_save(lua_State* L) {
  Mesh& m = self(L);
  std::string path = check_string(L, 2, "mesh:save path");
  std::string ext = std::filesystem::path(path).extension().string();
  if (ext != ".glb") throw Error("mesh:save: '" + path + "' must end in .glb (meshes are saved as binary glTF)");
  scene::save_glb(m, path);
  lua_pushstring(L, path.c_str());
  return 1;
}

// mesh:transformed{ translate = {x,y,z}, rotate = {degrees, ax, ay, az}, scale = s | {x,y,z},
//                   matrix = {16 numbers, column-major} } -> a new Mesh (scale, then rotate,
//                   then translate; `matrix` alone replaces the three)
int w_transformed(lua_State* L) {
  Mesh& m = self(L);
  Options o(L, 2, "mesh:transformed", {"translate", "rotate", "scale", "matrix"});
  glm::dmat4 t(1.0);
  if (o.has("matrix")) {
    if (o.has("translate") || o.has("rotate") || o.has("scale"))
      throw Error("mesh:transformed: give either 'matrix' or translate/rotate/scale, not both");
    auto v = o.numbers("matrix", 16);
    t = glm::make_mat4(v.data());
    // Positions are points (w = 1) and stay points: a projective bottom row would divide by w,
    // which the transform does not do, so it is refused rather than ignored.
    if (!(v[3] == 0 && v[7] == 0 && v[11] == 0 && v[15] == 1))
      throw Error(o.where("matrix") + ": an affine transform expected, whose bottom row (elements 4, 8, 12, 16, "
                  "column-major) is 0 0 0 1; got " + io::number_text(v[3]) + " " + io::number_text(v[7]) + " " +
                  io::number_text(v[11]) + " " + io::number_text(v[15]));
  } else {
    if (o.has("translate")) {
      auto v = o.numbers("translate", 3);
      t = glm::translate(t, glm::dvec3(v[0], v[1], v[2]));
    }
    if (o.has("rotate")) {
      auto v = o.numbers("rotate", 4);
      glm::dvec3 axis(v[1], v[2], v[3]);
      if (!(glm::length(axis) > 0)) throw Error("mesh:transformed option 'rotate': the axis {ax, ay, az} is zero");
      t = glm::rotate(t, glm::radians(v[0]), glm::normalize(axis));
    }
    if (o.has("scale")) {
      int i = o.push("scale");
      glm::dvec3 s;
      if (lua_type(L, i) == LUA_TNUMBER) {
        s = glm::dvec3(lua_tonumber(L, i));
      } else {
        auto v = check_numbers(L, i, o.where("scale").c_str(), 3);
        s = glm::dvec3(v[0], v[1], v[2]);
      }
      lua_pop(L, 1);
      t = glm::scale(t, s);
    }
  }
  try {
    push_mesh(L, scene::transformed(m, t));
  } catch (const std::invalid_argument& e) {
    throw Error(std::string("mesh:transformed: ") + e.what());
  }
  return 1;
}

int w_tostring(lua_State* L) {
  auto* ud = static_cast<Box<Mesh>*>(test_type(L, 1, kType));
  if (!ud || !ud->ptr) return lua_pushstring(L, "Mesh (released)"), 1;
  const Mesh& m = *ud->ptr;
  std::string s = "Mesh(" + m.name + ": " + std::to_string(m.vertex_count()) + " vertices, " +
                  std::to_string(m.triangle_count()) + " triangles";
  if (m.has_normals) s += m.normals_computed ? ", computed normals" : ", normals";
  if (m.has_uvs) s += ", uvs";
  if (m.base_color) {
    try {
      s += ", texture " + std::to_string(m.base_color->width) + "x" + std::to_string(m.base_color->height);
    } catch (const std::exception&) {  // printing a mesh is no place for its texture's error
      s += ", texture (unreadable: mesh:texture() says why)";
    }
  }
  lua_pushstring(L, (s + ")").c_str());
  return 1;
}

}  // namespace

void open_mesh(lua_State* L) {
  static const luaL_Reg methods[] = {SN_FN("counts", w_counts),
                                     SN_FN("has", w_has),
                                     SN_FN("normals_computed", w_normals_computed),
                                     SN_FN("bounds", w_bounds),
                                     SN_FN("texture", w_texture),
                                     SN_FN("name", w_name),
                                     SN_FN("key", w_key),
                                     SN_FN("save", w_save),
                                     SN_FN("transformed", w_transformed),
                                     {nullptr, nullptr}};
  define_box_type<Mesh>(L, kType, methods, wrap<w_tostring>);
  static const luaL_Reg fns[] = {SN_FN("load", w_load), SN_FN("sphere", w_sphere), SN_FN("torus", w_torus),
                                 SN_FN("plane", w_plane), {nullptr, nullptr}};
  lua_newtable(L);
  for (const luaL_Reg* r = fns; r->name; ++r) {
    lua_pushcfunction(L, r->func);
    lua_setfield(L, -2, r->name);
  }
  lua_setfield(L, -2, "mesh");
}

}  // namespace sn::lua

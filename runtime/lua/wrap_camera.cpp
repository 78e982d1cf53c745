// sn.camera{...} and sn.orbit{...}: look-at + perspective cameras, as Camera objects.
#include <glm/gtc/type_ptr.hpp>

#include "io/text.h"
#include "lua/binding.h"
#include "lua/module.h"
#include "scene/camera.h"

namespace sn::lua {

namespace {

constexpr const char* kType = "Camera";
using scene::Camera;

Camera& self(lua_State* L) { return check<Camera>(L, 1, kType); }

void push_numbers(lua_State* L, const double* v, int n) {
  lua_createtable(L, n, 0);
  for (int i = 0; i < n; ++i) {
    lua_pushnumber(L, v[i]);
    lua_rawseti(L, -2, i + 1);
  }
}

glm::dvec3 vec3(const Options& o, const char* key, glm::dvec3 def) {
  if (!o.has(key)) return def;
  auto v = o.numbers(key, 3);
  return {v[0], v[1], v[2]};
}

// sn.camera{ eye = {0,0,3}, target = {0,0,0}, up = {0,1,0}, fov = 45 (vertical, degrees),
//            near = 0.1, far = 100, aspect = width/height (default: the render target's) }
int w_new(lua_State* L) {
  Options o(L, 1, "sn.camera", {"eye", "target", "up", "fov", "near", "far", "aspect"});
  double aspect = o.number("aspect", 0);
  if (o.has("aspect") && !(aspect > 0)) throw Error("sn.camera option 'aspect' must be > 0");
  push(L,
       std::make_shared<Camera>(vec3(o, "eye", {0, 0, 3}), vec3(o, "target", {0, 0, 0}), vec3(o, "up", {0, 1, 0}),
                                o.number("fov", 45), aspect, o.number("near", 0.1), o.number("far", 100)),
       kType);
  return 1;
}

// sn.orbit{ count = 8, elevation = 20, distance = 3, target = {0,0,0}, fov = 45, near, far, aspect }
//   -> { camera1, ..., cameraN } evenly around the Y axis
int w_orbit(lua_State* L) {
  scene::OrbitOptions oo;
  if (!lua_isnoneornil(L, 1)) {
    Options o(L, 1, "sn.orbit", {"count", "elevation", "distance", "target", "fov", "near", "far", "aspect"});
    oo.count = o.int32("count", oo.count);
    oo.elevation = o.number("elevation", oo.elevation);
    oo.distance = o.number("distance", oo.distance);
    oo.target = vec3(o, "target", oo.target);
    oo.fov_y = o.number("fov", oo.fov_y);
    oo.near = o.number("near", oo.near);
    oo.far = o.number("far", oo.far);
    oo.aspect = o.number("aspect", 0);
    if (o.has("aspect") && !(oo.aspect > 0)) throw Error("sn.orbit option 'aspect' must be > 0");
  }
  auto cams = scene::orbit(oo);
  lua_createtable(L, int(cams.size()), 0);
  for (size_t i = 0; i < cams.size(); ++i) {
    push(L, std::make_shared<Camera>(cams[i]), kType);
    lua_rawseti(L, -2, int(i + 1));
  }
  return 1;
}

// camera:view() -> 16 numbers, column-major
int w_view(lua_State* L) {
  glm::dmat4 m = self(L).view();
  push_numbers(L, glm::value_ptr(m), 16);
  return 1;
}

// camera:projection([aspect]) -> 16 numbers, column-major
int w_projection(lua_State* L) {
  Camera& c = self(L);
  double aspect = lua_isnoneornil(L, 2) ? c.aspect() : check_number(L, 2, "camera:projection aspect");
  if (aspect == 0)
    throw Error("camera:projection: this camera follows its render target's aspect; pass one, e.g. "
                "camera:projection(width / height)");
  glm::dmat4 m = c.projection(aspect);
  push_numbers(L, glm::value_ptr(m), 16);
  return 1;
}

int w_eye(lua_State* L) {
  push_numbers(L, glm::value_ptr(self(L).eye()), 3);
  return 1;
}

int w_target(lua_State* L) {
  push_numbers(L, glm::value_ptr(self(L).target()), 3);
  return 1;
}

// camera:fov() -> vertical field of view in degrees; camera:aspect() -> number or nil
int w_fov(lua_State* L) {
  lua_pushnumber(L, self(L).fov_y());
  return 1;
}
int w_aspect(lua_State* L) {
  Camera& c = self(L);
  if (c.aspect() > 0) lua_pushnumber(L, c.aspect());
  else lua_pushnil(L);
  return 1;
}

// camera:ray(x, y, width, height) -> origin {3}, direction {3} (unit), through the centre of
// pixel (x, y) of a width x height image; x, y are 1-based from the top-left, as in image:get.
int w_ray(lua_State* L) {
  Camera& c = self(L);
  double x = check_number(L, 2, "camera:ray x"), y = check_number(L, 3, "camera:ray y");
  // int32 checked before the cast: 2^53 wrapped and was called "smaller than 1x1".
  const int w = check_int32(L, 4, "camera:ray width"), h = check_int32(L, 5, "camera:ray height");
  if (w < 1 || h < 1) throw Error("camera:ray: width and height must be at least 1");
  // Fractional x, y reach inside a pixel; past the image's edges is a mistake (x for y, 0-based).
  if (!(x >= 0.5 && x <= double(w) + 0.5) || !(y >= 0.5 && y <= double(h) + 0.5))
    throw Error("camera:ray: pixel (" + io::number_text(x) + ", " + io::number_text(y) + ") is outside the " +
                std::to_string(w) + " x " + std::to_string(h) + " image (x in 0.5.." + std::to_string(w) +
                ".5, y in 0.5.." + std::to_string(h) + ".5; whole numbers are pixel centres)");
  scene::Ray r = c.ray(x - 1, y - 1, w, h);
  push_numbers(L, glm::value_ptr(r.origin), 3);
  push_numbers(L, glm::value_ptr(r.direction), 3);
  return 2;
}

int w_tostring(lua_State* L) {
  auto* ud = static_cast<Box<Camera>*>(test_type(L, 1, kType));
  if (!ud || !ud->ptr) return lua_pushstring(L, "Camera (released)"), 1;
  const Camera& c = *ud->ptr;
  char buf[256];
  snprintf(buf, sizeof buf, "Camera(eye = {%g, %g, %g}, target = {%g, %g, %g}, fov = %g)", c.eye().x, c.eye().y,
           c.eye().z, c.target().x, c.target().y, c.target().z, c.fov_y());
  lua_pushstring(L, buf);
  return 1;
}

}  // namespace

void open_camera(lua_State* L) {
  static const luaL_Reg methods[] = {SN_FN("view", w_view),     SN_FN("projection", w_projection),
                                     SN_FN("eye", w_eye),       SN_FN("target", w_target),
                                     SN_FN("fov", w_fov),       SN_FN("aspect", w_aspect),
                                     SN_FN("ray", w_ray),       {nullptr, nullptr}};
  define_box_type<Camera>(L, kType, methods, wrap<w_tostring>);
  lua_pushcfunction(L, wrap<w_new>);
  lua_setfield(L, -2, "camera");
  lua_pushcfunction(L, wrap<w_orbit>);
  lua_setfield(L, -2, "orbit");
}

}  // namespace sn::lua

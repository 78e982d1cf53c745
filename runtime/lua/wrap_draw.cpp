// sn.draw{...}: one mesh, seen by one camera, drawn with one graphics program into a target.
#include <glm/gtc/type_ptr.hpp>

#include "gl/program.h"
#include "gl/render_target.h"
#include "lua/binding.h"
#include "lua/module.h"
#include "lua/program_bindings.h"
#include "scene/camera.h"
#include "scene/gpu_mesh.h"
#include "scene/mesh.h"

namespace sn::lua {

namespace {

// sn.draw{ target = t, program = p, mesh = m, camera = c, model = {16 numbers} (identity),
//          clear = {r,g,b,a} (keep what is there), cull = "none" | "back" | "front",
//          uniforms = {...}, buffers = {...}, textures = {...} } -> target
int w_draw(lua_State* L) {
  Options o(L, 1, "sn.draw",
            {"target", "program", "mesh", "camera", "model", "clear", "cull", "uniforms", "buffers", "textures"});
  auto required = [&](const char* key, const char* type) {
    int i = o.push(key);
    if (lua_isnil(L, i)) throw Error(o.where(key) + " is required (a " + type + ")");
    if (!test_type(L, i, type)) throw Error(o.where(key) + ": " + type + " expected, got " + type_name_at(L, i));
    return i;
  };
  // Each object stays on the stack (so it cannot be collected) until we return.
  auto& target = check<gl::RenderTarget>(L, required("target", "Target"), "Target");
  auto& program = check<gl::Program>(L, required("program", "Program"), "Program");
  auto& mesh = check<scene::Mesh>(L, required("mesh", "Mesh"), "Mesh");
  auto& camera = check<scene::Camera>(L, required("camera", "Camera"), "Camera");
  if (program.is_compute())
    throw Error(o.where("program") + ": " + program.name() + " is a compute program; sn.draw needs vertex + fragment");

  glm::dmat4 model(1.0);
  if (o.has("model")) {
    auto v = o.numbers("model", 16);
    model = glm::make_mat4(v.data());
  }
  auto cull = scene::Cull(o.choice("cull", {"none", "back", "front"}, 0));

  scene::GpuMesh& gpu = scene::upload(mesh);
  target.bind();
  if (o.has("clear")) {
    auto c = o.finite_numbers("clear", 4, true);
    target.clear({float(c[0]), float(c[1]), float(c[2]), float(c[3])});
  }
  scene::set_standard_uniforms(program, camera, camera.aspect_for(target.width(), target.height()), model, gpu);
  apply_bindings(L, o, program);  // the script's own uniforms come last and may override the standard ones
  scene::draw(program, gpu, model, cull);
  lua_pushvalue(L, required("target", "Target"));
  return 1;
}

}  // namespace

void open_draw(lua_State* L) {
  lua_pushcfunction(L, wrap<w_draw>);
  lua_setfield(L, -2, "draw");
}

}  // namespace sn::lua

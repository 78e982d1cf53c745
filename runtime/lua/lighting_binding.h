// Shared by the bindings that take lighting models and lights (wrap_lighting.cpp,
// wrap_lighting_define.cpp, wrap_scene.cpp).
#pragma once
#include <string>
#include <vector>

#include "lua/binding.h"
#include "scene/light.h"
#include "shading/lighting_params.h"

namespace sn::lua {

constexpr const char* kLightingType = "Lighting";

// The lighting model at idx; otherwise an error naming `what` and what was given instead.
shading::LightingParams& check_lighting(lua_State* L, int idx, const std::string& what);

// A light from a table { dir = {x,y,z}, color = {r,g,b} } (either may be left out: the default's
// is used); `what` names it in errors.
scene::Light check_light(lua_State* L, int idx, const char* what, const scene::Light& def = {});
void push_light(lua_State* L, const scene::Light& l);
// The lights of sn.lighting.stress / check: a list of light tables at `idx`, or (none) the stress
// test's two lights. `fn` names the function in errors.
std::vector<scene::Light> check_lights(lua_State* L, int idx, const char* fn);
void push_vec3(lua_State* L, const glm::dvec3& v);
// Pushes a Lighting of model `m` with the parameters in the table at `idx` (nil = defaults).
int make_lighting(lua_State* L, const shading::ModelPtr& m, int idx);

// True for the names of sn.lighting's own functions (define, check, stress, ...): a model of
// that name could not be reached as sn.lighting.NAME{...}.
bool lighting_function_name(const std::string& name);

// sn.lighting.define{...} and sn.lighting.check(model) (wrap_lighting_define.cpp).
int w_define(lua_State* L);
int w_check(lua_State* L);

}  // namespace sn::lua

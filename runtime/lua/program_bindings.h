// Shared by every binding that runs a program (dispatch, draw): binds the `buffers`,
// `uniforms` and `textures` entries of an options table to `p`.
#pragma once
#include "gl/program.h"
#include "lua/binding.h"

namespace sn::lua {
void apply_bindings(lua_State* L, const Options& o, gl::Program& p);
}

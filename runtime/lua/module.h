// The `shadenet` Lua module: C++ bindings (one wrap_*.cpp per exposed type) plus the Lua-side
// prelude runtime/lua/shadenet.lua, embedded at build time.
#pragma once
#include <lua.hpp>

namespace sn::lua {

// Makes `require "shadenet"` (and the embedded "shadenet.*" modules) available in L.
void install(lua_State* L);

// Each binding file adds its functions to the module table on top of the stack.
void open_buffer(lua_State* L);
void open_program(lua_State* L);
void open_image(lua_State* L);
void open_figure(lua_State* L);  // after open_image: extends sn.image and Image
void open_terminal(lua_State* L);
void open_files(lua_State* L);
void open_target(lua_State* L);
void open_mesh(lua_State* L);
void open_camera(lua_State* L);
void open_draw(lua_State* L);
void open_context(lua_State* L);
void open_live(lua_State* L);
void open_mlp(lua_State* L);
void open_mlp_gl(lua_State* L);  // after open_mlp: net:forward, net:render, the "gl" backend
void open_dataset(lua_State* L);
void open_dataset_sample(lua_State* L);  // after open_dataset: sn.dataset.sample
void open_train(lua_State* L);
void open_activation(lua_State* L);  // sn.activation.*
void open_encoding(lua_State* L);    // sn.encoding.*
void open_lighting(lua_State* L);  // sn.lighting.*, sn.color.*
void open_scene(lua_State* L);     // sn.scene, sn.render_truth, sn.dataset_stats

// Dataset methods that live in their own files; open_dataset lists them.
int dataset_coverage(lua_State* L);  // ds:coverage{...}, wrap_coverage.cpp

}  // namespace sn::lua

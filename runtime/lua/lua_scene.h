// The "Scene" userdata: a scene plus what building it noticed (computed normals), for
// scene:notes(). Shared by wrap_scene.cpp, which makes it, and the bindings that take a Scene.
#pragma once
#include <string>
#include <vector>

#include "scene/scene.h"

namespace sn::lua {

inline constexpr const char* kSceneType = "Scene";

struct LuaScene {
  scene::Scene scene;
  std::vector<std::string> notes;
};

}  // namespace sn::lua

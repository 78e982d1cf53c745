// sn.live_compose{...}: the live view's error heatmap and side-by-side panel on the GPU
// (runtime/live/compose.h). The Lua side (shadenet.live.lua) calls it for sn.live.render.
#include <filesystem>

#include "gl/render_target.h"
#include "live/compose.h"
#include "lua/binding.h"
#include "lua/module.h"

namespace sn::lua {

namespace {

// sn.live_compose{ network = Target, truth = Target, layout = "error" | "side", scale = 0.25,
//                  colormap = "inferno" | "viridis" | "gray",
//                  into = Target (reused when it has the right size) } -> Target
int w_compose(lua_State* L) {
  Options o(L, 1, "sn.live_compose", {"network", "truth", "layout", "scale", "colormap", "into"});
  auto target = [&](const char* key) -> gl::RenderTarget& {
    int i = o.push(key);
    if (lua_isnil(L, i)) throw Error(o.where(key) + " is required (a Target)");
    if (!test_type(L, i, "Target")) throw Error(o.where(key) + ": Target expected, got " + type_name_at(L, i));
    return check<gl::RenderTarget>(L, i, "Target");
  };
  gl::RenderTarget& network = target("network");
  gl::RenderTarget& truth = target("truth");
  auto layout = live::Layout(o.choice("layout", {"error", "side"}, 0));
  double scale = o.number("scale", 0.25);
  auto map = io::Colormap(o.choice("colormap", {"inferno", "viridis", "gray"}, 0));
  auto [w, h] = live::composed_size(layout, network.width(), network.height());
  int into = o.push("into");
  if (!lua_isnil(L, into)) {
    auto& out = check<gl::RenderTarget>(L, into, "Target");
    if (out.width() == w && out.height() == h) {
      live::compose(layout, network, truth, scale, map, out);
      lua_pushvalue(L, into);
      return 1;
    }
  }
  auto out = std::make_shared<gl::RenderTarget>(w, h);
  live::compose(layout, network, truth, scale, map, *out);
  push(L, std::move(out), "Target");
  return 1;
}

// sn.live_absolute(path) -> the absolute, normalised path (for messages naming saved files)
int w_absolute(lua_State* L) {
  std::string p = check_string(L, 1, "path");
  lua_pushstring(L, std::filesystem::absolute(p).lexically_normal().string().c_str());
  return 1;
}

}  // namespace

void open_live(lua_State* L) {
  lua_pushcfunction(L, wrap<w_compose>);
  lua_setfield(L, -2, "live_compose");
  lua_pushcfunction(L, wrap<w_absolute>);
  lua_setfield(L, -2, "live_absolute");
}

}  // namespace sn::lua

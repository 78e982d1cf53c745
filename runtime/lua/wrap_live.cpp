// sn.live_compose{...}: the live view's error heatmap and side-by-side panel on the GPU
// (runtime/gl/compose.h, its twin io/compose.h), and sn.live_upload(image) for views rendered to Images. The Lua
// side (runtime/live/shadenet.live.view.lua) calls them for sn.live.render.
#include <epoxy/gl.h>

#include <algorithm>
#include <filesystem>

#include "gl/render_target.h"
#include "io/image.h"
#include "gl/compose.h"
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
  auto layout = io::Layout(o.choice("layout", {"error", "side"}, 0));
  double scale = o.number("scale", 0.25);
  auto map = io::Colormap(o.choice("colormap", {"inferno", "viridis", "gray"}, 0));
  auto [w, h] = io::composed_size(layout, network.width(), network.height());
  int into = o.push("into");
  if (!lua_isnil(L, into)) {
    auto& out = check<gl::RenderTarget>(L, into, "Target");
    if (out.width() == w && out.height() == h) {
      gl::compose(layout, network, truth, scale, map, out);
      lua_pushvalue(L, into);
      return 1;
    }
  }
  auto out = std::make_shared<gl::RenderTarget>(w, h);
  gl::compose(layout, network, truth, scale, map, *out);
  push(L, std::move(out), "Target");
  return 1;
}

// sn.live_upload(image [, into]) -> Target holding the image (rows top first, as Image keeps
// them) in attachment 1, for views whose renders come back as Images (scene:render). RGB gets
// alpha 1, one channel is grey. `into` is reused when it has the image's size.
int w_upload(lua_State* L) {
  const io::Image& img = check<io::Image>(L, 1, "Image");
  if (img.channels != 1 && img.channels != 3 && img.channels != 4)
    throw Error("sn.live_upload: an image of 1, 3 or 4 channels expected, got " + std::to_string(img.channels));
  const size_t row = size_t(img.width) * 4;
  std::vector<float> rgba(row * img.height);
  for (int y = 0; y < img.height; ++y) {  // GL rows start at the bottom
    float* o = &rgba[size_t(img.height - 1 - y) * row];
    const float* in = &img.pixels[size_t(y) * img.width * img.channels];
    if (img.channels == 4) {
      std::copy(in, in + row, o);
      continue;
    }
    for (int x = 0; x < img.width; ++x, o += 4, in += img.channels) {
      if (img.channels == 1) o[0] = o[1] = o[2] = in[0];
      else o[0] = in[0], o[1] = in[1], o[2] = in[2];
      o[3] = 1;
    }
  }
  std::shared_ptr<gl::RenderTarget> out;
  if (!lua_isnoneornil(L, 2)) {
    auto& into = check_box<gl::RenderTarget>(L, 2, "Target");
    if (into->width() == img.width && into->height() == img.height) out = into;
  }
  bool reused = out != nullptr;
  if (!out) out = std::make_shared<gl::RenderTarget>(img.width, img.height);
  glTextureSubImage2D(out->color_texture(0), 0, 0, 0, img.width, img.height, GL_RGBA, GL_FLOAT, rgba.data());
  out->mark_drawn();
  if (reused) lua_pushvalue(L, 2);
  else push(L, std::move(out), "Target");
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
  lua_pushcfunction(L, wrap<w_upload>);
  lua_setfield(L, -2, "live_upload");
  lua_pushcfunction(L, wrap<w_absolute>);
  lua_setfield(L, -2, "live_absolute");
}

}  // namespace sn::lua

// sn.target{...}: offscreen render targets (float colour + depth) and sn.present(target).
#include "gl/context.h"
#include "gl/render_target.h"
#include "lua/binding.h"
#include "lua/module.h"

namespace sn::lua {

namespace {

constexpr const char* kType = "Target";
using gl::RenderTarget;

RenderTarget& self(lua_State* L) { return check<RenderTarget>(L, 1, kType); }

// sn.target{ width, height, colors = 1 }
int w_new(lua_State* L) {
  Options o(L, 1, "sn.target", {"width", "height", "colors"});
  push(L, std::make_shared<RenderTarget>(o.int32("width"), o.int32("height"), o.int32("colors", 1)),
       kType);
  return 1;
}

int w_clear(lua_State* L) {
  std::array<float, 4> c = {0, 0, 0, 0};
  RenderTarget& t = self(L);
  if (!lua_isnoneornil(L, 2)) {
    auto v = check_numbers(L, 2, "target:clear colour", 4);
    check_finite(v, "target:clear colour", true);
    for (int i = 0; i < 4; ++i) c[i] = float(v[i]);
  }
  t.clear(c);
  return 0;
}

// target:read([attachment = 1]) -> Image (RGBA float, top row first)
int w_read(lua_State* L) {
  RenderTarget& t = self(L);
  int i = lua_isnoneornil(L, 2) ? 0 : check_int32(L, 2, "attachment") - 1;
  push(L, std::make_shared<io::Image>(t.read(i)), "Image");
  return 1;
}

// target:pixel(x, y [, attachment = 1]) -> {r, g, b, a} (1-based from the top-left, as image:get)
int w_pixel(lua_State* L) {
  RenderTarget& t = self(L);
  int x = check_int32(L, 2, "x"), y = check_int32(L, 3, "y");
  int i = lua_isnoneornil(L, 4) ? 0 : check_int32(L, 4, "attachment") - 1;
  auto p = t.pixel(x - 1, y - 1, i);
  lua_createtable(L, 4, 0);
  for (int c = 0; c < 4; ++c) lua_pushnumber(L, p[c]), lua_rawseti(L, -2, c + 1);
  return 1;
}

int w_size(lua_State* L) {
  RenderTarget& t = self(L);
  lua_pushinteger(L, t.width()), lua_pushinteger(L, t.height());
  return 2;
}

// sn.present(target): shows attachment 1 in the window (no-op headless); returns false once
// the window was closed.
int w_present(lua_State* L) {
  RenderTarget& t = check<RenderTarget>(L, 1, kType);
  auto& ctx = gl::current();
  ctx.present(t.fbo(), t.width(), t.height());
  ctx.poll();
  lua_pushboolean(L, !ctx.should_close());
  return 1;
}

// sn.screenshot(target) -> Image: presents the target and reads back what the window shows
// (the whole window, letterboxed); headless it is an error.
int w_screenshot(lua_State* L) {
  RenderTarget& t = check<RenderTarget>(L, 1, kType);
  auto& ctx = gl::current();
  if (!ctx.windowed()) throw Error("sn.screenshot needs a window: run with --window (headless, use target:read())");
  auto img = std::make_shared<io::Image>();
  ctx.present(t.fbo(), t.width(), t.height(), img.get());
  push(L, std::move(img), "Image");
  return 1;
}

// sn.window_size() -> width, height of the window's framebuffer (0, 0 headless)
int w_window_size(lua_State* L) {
  auto [w, h] = gl::current().framebuffer_size();
  lua_pushinteger(L, w), lua_pushinteger(L, h);
  return 2;
}

int w_tostring(lua_State* L) {
  auto* ud = static_cast<Box<RenderTarget>*>(test_type(L, 1, kType));
  if (!ud || !ud->ptr) lua_pushstring(L, "Target (released)");
  else lua_pushfstring(L, "Target(%dx%d, %d colours)", ud->ptr->width(), ud->ptr->height(), ud->ptr->attachments());
  return 1;
}

}  // namespace

void open_target(lua_State* L) {
  static const luaL_Reg methods[] = {SN_FN("clear", w_clear), SN_FN("read", w_read), SN_FN("pixel", w_pixel),
                                     SN_FN("size", w_size),
                                     {nullptr, nullptr}};
  define_box_type<RenderTarget>(L, kType, methods, wrap<w_tostring>);
  lua_pushcfunction(L, wrap<w_new>);
  lua_setfield(L, -2, "target");
  lua_pushcfunction(L, wrap<w_present>);
  lua_setfield(L, -2, "present");
  lua_pushcfunction(L, wrap<w_screenshot>);
  lua_setfield(L, -2, "screenshot");
  lua_pushcfunction(L, wrap<w_window_size>);
  lua_setfield(L, -2, "window_size");
}

}  // namespace sn::lua

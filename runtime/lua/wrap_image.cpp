// sn.image.*: float images in memory, PNG/EXR files through OpenImageIO, differences and MSE.
#include <cmath>

#include "io/image.h"
#include "io/ssim.h"
#include "lua/binding.h"
#include "lua/module.h"

namespace sn::lua {

namespace {

constexpr const char* kType = "Image";
using io::Image;

Image& self(lua_State* L) { return check<Image>(L, 1, kType); }

int w_load(lua_State* L) {
  push(L, std::make_shared<Image>(io::load_image(check_string(L, 1, "sn.image.load path"))), kType);
  return 1;
}

// sn.image.new{ width, height, channels = 4, fill = 0 }
int w_new(lua_State* L) {
  Options o(L, 1, "sn.image.new", {"width", "height", "channels", "fill"});
  long long w = o.integer("width"), h = o.integer("height"), c = o.integer("channels", 4);
  if (w < 1 || h < 1 || w > 65536 || h > 65536) throw Error("sn.image.new: size must be 1..65536 on each side");
  if (c < 1 || c > 4) throw Error("sn.image.new: channels must be 1..4, got " + std::to_string(c));
  push(L, std::make_shared<Image>(int(w), int(h), int(c), float(o.number("fill", 0))), kType);
  return 1;
}

int w_save(lua_State* L) {
  std::string path = check_string(L, 2, "image:save path");
  io::save_image(self(L), path);
  lua_pushstring(L, path.c_str());
  return 1;
}

int w_size(lua_State* L) {
  Image& i = self(L);
  lua_pushinteger(L, i.width), lua_pushinteger(L, i.height), lua_pushinteger(L, i.channels);
  return 3;
}

void check_xy(const Image& img, long long x, long long y) {
  if (x < 1 || x > img.width || y < 1 || y > img.height)
    throw Error("pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") outside the image's 1.." +
                std::to_string(img.width) + " x 1.." + std::to_string(img.height));
}

// img:get(x, y) -> {r, g, b, a}; x, y 1-based from the top-left corner
int w_get(lua_State* L) {
  Image& img = self(L);
  long long x = check_integer(L, 2, "x"), y = check_integer(L, 3, "y");
  check_xy(img, x, y);
  lua_createtable(L, img.channels, 0);
  for (int c = 0; c < img.channels; ++c) {
    lua_pushnumber(L, img.at(int(x - 1), int(y - 1), c));
    lua_rawseti(L, -2, c + 1);
  }
  return 1;
}

int w_set(lua_State* L) {
  Image& img = self(L);
  long long x = check_integer(L, 2, "x"), y = check_integer(L, 3, "y");
  check_xy(img, x, y);
  auto v = check_numbers(L, 4, "image:set value", img.channels);
  for (int c = 0; c < img.channels; ++c) img.at(int(x - 1), int(y - 1), c) = float(v[c]);
  return 0;
}

int w_diff(lua_State* L) {
  push(L, std::make_shared<Image>(io::difference(check<Image>(L, 1, kType), check<Image>(L, 2, kType))), kType);
  return 1;
}

// What sn.image.mse and sn.image.ssim compare: { channels = the colour ones, mask = img,
// mask_channel = 4 }. The colour channels are 3 of 3 or 4 and 1 of 1 or 2: alpha (coverage) is
// not compared unless asked for (it was, by default, and a channel count past the image's meant
// all of them).
struct Compared {
  int channels = 0, mask_channel = 3;
  const Image* mask = nullptr;
};
Compared compared(lua_State* L, const char* what) {
  const Image& a = check<Image>(L, 1, kType);
  Compared c;
  c.channels = a.channels >= 3 ? 3 : 1;
  if (lua_isnoneornil(L, 3)) return c;
  Options o(L, 3, what, {"channels", "mask", "mask_channel"});
  c.channels = o.int32("channels", c.channels);
  if (c.channels < 1 || c.channels > a.channels)
    throw Error(o.where("channels") + " must be 1.." + std::to_string(a.channels) + " (the image's channels), got " +
                std::to_string(c.channels));
  c.mask_channel = o.int32("mask_channel", 4) - 1;
  int m = o.push("mask");
  if (!lua_isnil(L, m)) c.mask = &check<Image>(L, m, kType);  // stays referenced by the options table
  lua_pop(L, 1);
  if (c.mask && (c.mask_channel < 0 || c.mask_channel >= c.mask->channels))
    throw Error(o.where("mask_channel") + " must be 1.." + std::to_string(c.mask->channels) +
                " (the mask's channels), got " + std::to_string(c.mask_channel + 1));
  return c;
}

// sn.image.mse(a, b [, options]) -> mean squared error
int w_mse(lua_State* L) {
  Compared c = compared(L, "sn.image.mse");
  const Image &a = check<Image>(L, 1, kType), &b = check<Image>(L, 2, kType);
  const double e = io::mse(a, b, c.channels, c.mask, c.mask_channel);
  if (!std::isfinite(e)) {  // an error naming the pixel, as sn.image.ssim's, not a NaN or inf to carry on with
    io::check_finite(a, c.channels, "sn.image.mse: image 1");
    io::check_finite(b, c.channels, "sn.image.mse: image 2");
  }
  lua_pushnumber(L, e);
  return 1;
}

// sn.image.ssim(a, b [, options]) -> mean SSIM (io/ssim.h)
int w_ssim(lua_State* L) {
  Compared c = compared(L, "sn.image.ssim");
  lua_pushnumber(L, io::ssim(check<Image>(L, 1, kType), check<Image>(L, 2, kType), c.channels, c.mask, c.mask_channel));
  return 1;
}

int w_tostring(lua_State* L) {
  auto* ud = static_cast<Box<Image>*>(test_type(L, 1, kType));
  if (!ud || !ud->ptr) lua_pushstring(L, "Image (released)");
  else lua_pushfstring(L, "Image(%dx%d, %d channels)", ud->ptr->width, ud->ptr->height, ud->ptr->channels);
  return 1;
}

}  // namespace

void open_image(lua_State* L) {
  static const luaL_Reg methods[] = {SN_FN("save", w_save), SN_FN("size", w_size), SN_FN("get", w_get),
                                     SN_FN("set", w_set), {nullptr, nullptr}};
  define_box_type<Image>(L, kType, methods, wrap<w_tostring>);
  static const luaL_Reg fns[] = {SN_FN("load", w_load), SN_FN("new", w_new), SN_FN("diff", w_diff),
                                 SN_FN("mse", w_mse), SN_FN("ssim", w_ssim), {nullptr, nullptr}};
  lua_newtable(L);
  luaL_register(L, nullptr, fns);
  lua_setfield(L, -2, "image");
}

}  // namespace sn::lua

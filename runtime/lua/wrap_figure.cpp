// Figures: sn.image.grid{...}, sn.image.heatmap(diff, {...}), sn.image.text_size(text, size),
// sn.image.crop(img, x, y, w, h), sn.image.covered_box(img), sn.image.clamp(img) and
// img:text(x, y, "label", {...}). Added to the sn.image table and the Image type that
// wrap_image.cpp defines, so open_figure runs after open_image.
#include <cmath>

#include "io/figure.h"
#include "lua/binding.h"
#include "lua/module.h"

namespace sn::lua {

namespace {

constexpr const char* kType = "Image";
using io::Image;

io::Color color_option(const Options& o, const char* key, io::Color def) {
  if (!o.has(key)) return def;
  auto v = o.finite_numbers(key, 3, true);  // a NaN colour wrote NaN pixels
  return {float(v[0]), float(v[1]), float(v[2])};
}

// img:text(x, y, "label", { size = 16, color = {1,1,1}, align = "left" }) -> img
// x, y: 1-based pixel of the text line's top-left (top-centre, top-right with align).
int w_text(lua_State* L) {
  Image& img = check<Image>(L, 1, kType);
  // int32 checked: 2^32 + 2 drew at x = 2 through the int casts.
  const int x = check_int32(L, 2, "image:text x"), y = check_int32(L, 3, "image:text y");
  std::string text = check_string(L, 4, "image:text label");
  io::TextStyle style;
  if (!lua_isnoneornil(L, 5)) {
    Options o(L, 5, "image:text", {"size", "color", "align"});
    style.size = float(o.number("size", 16));
    if (!(style.size >= 4 && style.size <= 512))
      throw Error("image:text: size must be 4..512 pixels, got " + std::to_string(style.size));
    style.color = color_option(o, "color", style.color);
    style.align = io::Align(o.choice("align", {"left", "center", "right"}, 0));
  }
  io::draw_text(img, x - 1, y - 1, text, style);
  lua_pushvalue(L, 1);
  return 1;
}

// sn.image.text_size("label", size) -> width, height in pixels
int w_text_size(lua_State* L) {
  std::string text = check_string(L, 1, "sn.image.text_size label");
  double size = lua_isnoneornil(L, 2) ? 16 : check_number(L, 2, "sn.image.text_size size");
  auto wh = io::text_size(text, float(size));
  lua_pushinteger(L, wh[0]);
  lua_pushinteger(L, wh[1]);
  return 2;
}

// sn.image.grid{ panels = { img, {image = img, caption = "truth"}, ... }, captions = {...},
//                columns = 0, padding = 6, caption_size = 14, title = "", title_size = 18,
//                row_labels = {...}, background = {1,1,1}, text = {0,0,0} } -> Image (RGB)
int w_grid(lua_State* L) {
  Options o(L, 1, "sn.image.grid",
            {"panels", "captions", "columns", "padding", "caption_size", "title", "title_size", "row_labels",
             "background", "text"});
  io::GridStyle s;
  s.columns = o.int32("columns", 0);
  s.padding = o.int32("padding", s.padding);
  s.caption_size = float(o.number("caption_size", s.caption_size));
  s.title_size = float(o.number("title_size", s.title_size));
  s.title = o.string("title", "");
  s.background = color_option(o, "background", s.background);
  s.text = color_option(o, "text", s.text);

  std::vector<io::Panel> panels;
  int t = o.push("panels");
  if (!lua_istable(L, t)) throw Error("sn.image.grid option 'panels': a list of images expected, got " + type_name_at(L, t));
  const int n = check_list(L, t, "sn.image.grid option 'panels'");
  if (n == 0) throw Error("sn.image.grid option 'panels': the list is empty");
  for (int i = 1; i <= n; ++i) {
    lua_rawgeti(L, t, i);
    int p = lua_gettop(L);
    io::Panel panel;
    if (test_type(L, p, kType)) {
      panel.image = check<Image>(L, p, kType);
    } else if (lua_istable(L, p)) {
      Options po(L, p, "sn.image.grid panel", {"image", "caption"});
      int im = po.push("image");
      if (!test_type(L, im, kType))
        throw Error("sn.image.grid panel " + std::to_string(i) + ": 'image' must be an Image, got " + type_name_at(L, im));
      panel.image = check<Image>(L, im, kType);
      lua_pop(L, 1);
      panel.caption = po.string("caption", "");
    } else {
      throw Error("sn.image.grid panel " + std::to_string(i) + ": an Image or {image=, caption=} expected, got " +
                  type_name_at(L, p));
    }
    panels.push_back(std::move(panel));
    lua_pop(L, 1);
  }
  lua_pop(L, 1);

  auto strings = [&](const char* key) {
    std::vector<std::string> out;
    int k = o.push(key);
    if (!lua_isnil(L, k)) {
      if (!lua_istable(L, k)) throw Error(o.where(key) + ": a list of strings expected, got " + type_name_at(L, k));
      const int n = check_list(L, k, o.where(key));
      for (int i = 1; i <= n; ++i) {
        lua_rawgeti(L, k, i);
        out.push_back(check_string(L, -1, o.where(key).c_str()));
        lua_pop(L, 1);
      }
    }
    lua_pop(L, 1);
    return out;
  };
  auto captions = strings("captions");
  if (!captions.empty()) {
    if (captions.size() != panels.size())
      throw Error("sn.image.grid: " + std::to_string(captions.size()) + " captions for " +
                  std::to_string(panels.size()) + " panels");
    for (size_t i = 0; i < panels.size(); ++i) panels[i].caption = captions[i];
  }
  s.row_labels = strings("row_labels");
  push(L, std::make_shared<Image>(io::grid(panels, s)), kType);
  return 1;
}

// sn.image.heatmap(diff, { max = 0 (auto), colormap = "inferno", colorbar = true, label = "",
//                          mask = img, mask_channel = 4, background = {1,1,1}, text = {0,0,0} })
//   -> Image (RGB), max used, number of NaN/Inf pixels
int w_heatmap(lua_State* L) {
  Image& diff = check<Image>(L, 1, kType);
  io::HeatmapStyle s;
  if (!lua_isnoneornil(L, 2)) {
    Options o(L, 2, "sn.image.heatmap",
              {"max", "colormap", "colorbar", "label", "mask", "mask_channel", "background", "text"});
    s.max = o.number("max", 0);
    if (!std::isfinite(s.max) || s.max < 0) throw Error("sn.image.heatmap: max must be finite and >= 0 (0 = auto)");
    s.map = io::Colormap(o.choice("colormap", {"inferno", "viridis", "gray"}, 0));
    s.colorbar = o.boolean("colorbar", true);
    s.label = o.string("label", "");
    s.mask_channel = o.int32("mask_channel", 4) - 1;
    s.background = color_option(o, "background", s.background);
    s.text = color_option(o, "text", s.text);
    int m = o.push("mask");
    if (!lua_isnil(L, m)) s.mask = &check<Image>(L, m, kType);
    lua_pop(L, 1);
  }
  io::Heatmap h = io::heatmap(diff, s);
  push(L, std::make_shared<Image>(std::move(h.image)), kType);
  lua_pushnumber(L, h.max);
  lua_pushinteger(L, lua_Integer(h.non_finite));
  return 3;
}

// sn.image.crop(img, x, y, width, height) -> Image: the part at 1-based (x, y), top-left
int w_crop(lua_State* L) {
  Image& img = check<Image>(L, 1, kType);
  const int x = check_int32(L, 2, "sn.image.crop x"), y = check_int32(L, 3, "sn.image.crop y");
  const int w = check_int32(L, 4, "sn.image.crop width"), h = check_int32(L, 5, "sn.image.crop height");
  push(L, std::make_shared<Image>(io::crop(img, x - 1, y - 1, w, h)), kType);
  return 1;
}

// sn.image.clamp(img [, lo = 0, hi = 1]) -> Image: colour channels clamped as a display shows
// them (alpha kept, NaN kept)
int w_clamp(lua_State* L) {
  Image& img = check<Image>(L, 1, kType);
  double lo = lua_isnoneornil(L, 2) ? 0 : check_number(L, 2, "sn.image.clamp lo");
  double hi = lua_isnoneornil(L, 3) ? 1 : check_number(L, 3, "sn.image.clamp hi");
  push(L, std::make_shared<Image>(io::clamp_colors(img, float(lo), float(hi))), kType);
  return 1;
}

// sn.image.covered_box(img [, channel = 4]) -> x, y, width, height (1-based) of the pixels whose
// channel is > 0.5, or nil when none is
int w_covered_box(lua_State* L) {
  Image& img = check<Image>(L, 1, kType);
  const int c = lua_isnoneornil(L, 2) ? 4 : check_int32(L, 2, "sn.image.covered_box channel");
  io::Box b = io::covered_box(img, c - 1);
  if (b.width == 0) return 0;
  lua_pushinteger(L, b.x + 1);
  lua_pushinteger(L, b.y + 1);
  lua_pushinteger(L, b.width);
  lua_pushinteger(L, b.height);
  return 4;
}

}  // namespace

void open_figure(lua_State* L) {
  // Image methods: the type is defined by open_image; add :text to its method table.
  luaL_getmetatable(L, kType);
  if (!lua_istable(L, -1)) luaL_error(L, "internal: open_figure must run after open_image");
  lua_getfield(L, -1, "__index");
  lua_pushcfunction(L, wrap<w_text>);
  lua_setfield(L, -2, "text");
  lua_pop(L, 2);

  lua_getfield(L, -1, "image");
  if (!lua_istable(L, -1)) luaL_error(L, "internal: open_figure must run after open_image");
  static const luaL_Reg fns[] = {SN_FN("grid", w_grid),           SN_FN("heatmap", w_heatmap),
                                 SN_FN("text_size", w_text_size), SN_FN("crop", w_crop),
                                 SN_FN("covered_box", w_covered_box), SN_FN("clamp", w_clamp), {nullptr, nullptr}};
  luaL_register(L, nullptr, fns);
  lua_pop(L, 1);
}

}  // namespace sn::lua

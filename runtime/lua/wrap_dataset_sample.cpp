// sn.dataset.sample{...}: a "Dataset" sampled from a lighting model's domain rather than
// rendered from a scene (runtime/data/sample.h), cached like scene datasets.
#include <cmath>
#include <stdexcept>

#include "data/sample.h"
#include "io/text.h"
#include "lua/binding.h"
#include "lua/lighting_binding.h"
#include "lua/module.h"

namespace sn::lua {

namespace {

constexpr const char* kWhat = "sn.dataset.sample";

// Whole numbers in full ("16777217", not %g's "1.67772e+07"), anything else as %g.
std::string count_text(double v) {
  if (std::isnan(v)) return "nan";
  return std::abs(v) <= 0x1p53 && std::floor(v) == v ? std::to_string((long long)v) : io::number_text(v);
}

// A whole number in [lo, hi], read as a number first, so a huge or infinite value is refused
// rather than cast.
double whole_number(const Options& o, const char* key, double def, double lo, double hi, const std::string& meaning) {
  const double v = o.number(key, def);
  if (!(v >= lo && v <= hi) || std::floor(v) != v)
    throw Error(o.where(key) + " must be a whole number in " + count_text(lo) + ".." + count_text(hi) + " (" +
                meaning + "), got " + count_text(v));
  return v;
}

// sn.dataset.sample{ target = model, n = 64149, normals = "sphere", views = "uniform",
//                    axis = {0, 1, 0}, light = {dir, color}, seed = 1, split = 0.8, color = "rgb" }
int w_sample(lua_State* L) {
  Options o(L, 1, kWhat, {"target", "n", "normals", "views", "axis", "light", "seed", "split", "color"});
  data::SampleRequest r;
  int t = o.push("target");
  if (lua_isnil(L, t)) throw Error(o.where("target") + " is required (a lighting model, e.g. sn.lighting.ggx{})");
  r.target = check_lighting(L, t, o.where("target"));
  lua_pop(L, 1);
  r.n = std::size_t(whole_number(o, "n", double(data::kThesisSamples), 2, double(data::kMaxSampleRows),
                                 "rows, training and validation together"));
  try {
    r.normals = data::parse_normal_domain(o.string("normals", "sphere"));
  } catch (const std::invalid_argument& e) {
    throw Error(o.where("normals") + ": " + e.what());
  }
  try {
    r.views = data::parse_view_domain(o.string("views", "uniform"));
  } catch (const std::invalid_argument& e) {
    throw Error(o.where("views") + ": " + e.what());
  }
  if (o.has("axis")) {
    if (r.normals != data::NormalDomain::hemisphere)
      throw Error(o.where("axis") + " is for normals = \"hemisphere\" only (normals is \"" +
                  data::normal_domain_name(r.normals) + "\")");
    auto a = o.numbers("axis", 3);
    r.axis = {a[0], a[1], a[2]};
    const double len = glm::length(r.axis);
    if (!std::isfinite(len) || len < 1e-12)
      throw Error(o.where("axis") + " must be a non-zero, finite direction (the hemisphere's pole), got {" +
                  io::number_text(a[0]) + ", " + io::number_text(a[1]) + ", " + io::number_text(a[2]) + "}");
  }
  int li = o.push("light");
  r.light = check_light(L, li, "sn.dataset.sample option 'light'");
  lua_pop(L, 1);
  r.seed = o.seed("seed", 1);
  r.split = o.number("split", 0.8);
  try {
    r.color = shading::parse_color_space(o.string("color", "rgb"));
  } catch (const std::invalid_argument& e) {
    throw Error(o.where("color") + ": " + e.what());
  }
  try {
    data::validate(r);  // every refusal before any GPU work
  } catch (const std::invalid_argument& e) {
    throw Error(std::string(kWhat) + ": " + e.what());
  }
  push(L, data::cached_sample_dataset(r), "Dataset");
  return 1;
}

}  // namespace

void open_dataset_sample(lua_State* L) {
  lua_getfield(L, -1, "dataset");
  if (!lua_istable(L, -1)) luaL_error(L, "internal: open_dataset_sample needs sn.dataset (call open_dataset first)");
  lua_pushcfunction(L, wrap<w_sample>);
  lua_setfield(L, -2, "sample");
  lua_pop(L, 1);
}

}  // namespace sn::lua

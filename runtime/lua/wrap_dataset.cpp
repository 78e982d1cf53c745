// sn.dataset{...} and the "Dataset" type: training and validation rows for sn.train. Scenes
// make datasets from rendered samples (scene:dataset); this one is for scripts and tests that
// have their rows as Lua tables or buffers.
#include <algorithm>
#include <cmath>
#include <memory>

#include "gl/buffer.h"
#include "lua/binding.h"
#include "lua/module.h"
#include "data/combine.h"
#include "data/dataset.h"
#include "data/dataset_file.h"
#include "data/input_layout.h"
#include "nn/shuffle.h"
#include "scene/gbuffer.h"

namespace sn::lua {

namespace {

constexpr const char* kType = "Dataset";
using data::Dataset;

// Rows from a table of rows ({{...}, ...}) or a float buffer of width-wide rows.
std::vector<float> read_rows(lua_State* L, int idx, int* width, const char* key) {
  const std::string what = std::string("sn.dataset option '") + key + "'";
  std::vector<float> out;
  if (test_type(L, idx, "Buffer")) {
    auto& b = check<gl::Buffer>(L, idx, "Buffer");
    if (!gl::elem_info(b.type()).is_float) throw Error(what + ": buffer of floats expected, got " + gl::elem_info(b.type()).name);
    if (*width < 1) throw Error(what + " is a buffer: give its row width as '" + (key[0] == 'x' ? "inputs" : "outputs") + "'");
    out = b.download_floats();
    if (out.size() % std::size_t(*width))
      throw Error(what + ": " + std::to_string(out.size()) + " floats are not whole rows of " + std::to_string(*width));
  } else if (lua_istable(L, idx)) {
    const int rows = check_list(L, idx, what);
    for (int r = 1; r <= rows; ++r) {
      lua_rawgeti(L, idx, r);
      auto v = check_numbers(L, -1, (what + " row " + std::to_string(r)).c_str());
      lua_pop(L, 1);
      if (*width < 1) *width = int(v.size());
      if (int(v.size()) != *width)
        throw Error(what + " row " + std::to_string(r) + " has " + std::to_string(v.size()) + " values, expected " +
                    std::to_string(*width));
      for (double d : v) out.push_back(float(d));
    }
  } else {
    throw Error(what + ": table of rows or Buffer expected, got " + type_name_at(L, idx));
  }
  if (out.empty()) throw Error(what + " has no rows");
  for (std::size_t j = 0; j < out.size(); ++j)
    if (!std::isfinite(out[j]))
      throw Error(what + " row " + std::to_string(j / *width + 1) + " column " + std::to_string(j % *width + 1) + " is " +
                  (std::isnan(out[j]) ? "NaN" : "infinite"));
  return out;
}

// sn.dataset{ x = rows | Buffer, y = rows | Buffer, inputs, outputs, split = 0.8, seed = 1,
//             color = "rgb", input_names = {...} }
int w_new(lua_State* L) {
  Options o(L, 1, "sn.dataset", {"x", "y", "inputs", "outputs", "split", "seed", "color", "input_names"});
  auto d = std::make_shared<Dataset>();
  d->inputs = o.int32("inputs", 0);
  d->outputs = o.int32("outputs", 0);
  // 0 stands for "the rows' width"; a given width below 1 was taken as that, silently.
  for (const char* key : {"inputs", "outputs"})
    if (o.has(key) && o.int32(key) < 1)
      throw Error(o.where(key) + ": a row width of at least 1 expected, got " + std::to_string(o.int32(key)));
  if (!o.has("x")) throw Error("sn.dataset option 'x' is required");
  if (!o.has("y")) throw Error("sn.dataset option 'y' is required");
  int xi = o.push("x");
  std::vector<float> x = read_rows(L, xi, &d->inputs, "x");
  int yi = o.push("y");
  std::vector<float> y = read_rows(L, yi, &d->outputs, "y");
  lua_pop(L, 2);
  const std::size_t rows = x.size() / std::size_t(d->inputs);
  if (y.size() / std::size_t(d->outputs) != rows)
    throw Error("sn.dataset: x has " + std::to_string(rows) + " rows but y has " +
                std::to_string(y.size() / std::size_t(d->outputs)));
  if (rows >= (std::size_t(1) << 31)) throw Error("sn.dataset: more than 2^31 rows");
  const double split = o.number("split", 0.8);
  if (!(split > 0 && split <= 1)) throw Error("sn.dataset option 'split' must be in (0, 1], got " + io::number_text(split));
  const uint32_t seed = uint32_t(o.seed("seed", 1, kSeed32Max));  // the split's permutation is 32-bit
  d->color = shading::parse_color_space(o.string("color", "rgb"));
  int names = o.push("input_names");
  if (!lua_isnil(L, names)) {
    if (!lua_istable(L, names)) throw Error("sn.dataset option 'input_names': table of strings expected");
    const int n = check_list(L, names, "sn.dataset option 'input_names'");
    for (int i = 1; i <= n; ++i) {
      lua_rawgeti(L, names, i);
      d->input_names.push_back(check_string(L, -1, "sn.dataset option 'input_names'"));
      lua_pop(L, 1);
    }
    // Names that do not fit the rows trained, then made a checkpoint sn.load refused.
    try {
      data::input_layout(*d);
    } catch (const std::exception& e) {
      throw Error(o.where("input_names") + ": " + e.what());
    }
  }
  lua_pop(L, 1);

  // A seeded random split: rows in the order of a permutation, the first `split` of them train.
  const std::size_t train = data::train_rows(split, rows);
  nn::EpochShuffle order(seed, 0xffffffffu, uint32_t(rows));
  for (std::size_t k = 0; k < rows; ++k) {
    const std::size_t r = order(uint32_t(k));
    const bool t = k < train;
    auto& X = t ? d->train_x : d->val_x;
    auto& Y = t ? d->train_y : d->val_y;
    X.insert(X.end(), x.begin() + r * d->inputs, x.begin() + (r + 1) * d->inputs);
    Y.insert(Y.end(), y.begin() + r * d->outputs, y.begin() + (r + 1) * d->outputs);
  }
  push(L, std::move(d), kType);
  return 1;
}

// sn.dataset{...}: __call receives the sn.dataset table first.
int w_call(lua_State* L) {
  lua_remove(L, 1);
  return w_new(L);
}

Dataset& self(lua_State* L) { return check<Dataset>(L, 1, kType); }

// ds:counts() -> training rows, validation rows
int w_counts(lua_State* L) {
  const Dataset& d = self(L);
  lua_pushinteger(L, lua_Integer(d.train_count()));
  lua_pushinteger(L, lua_Integer(d.val_count()));
  return 2;
}

int w_inputs(lua_State* L) {
  lua_pushinteger(L, self(L).inputs);
  return 1;
}

int w_outputs(lua_State* L) {
  lua_pushinteger(L, self(L).outputs);
  return 1;
}

int w_color(lua_State* L) {
  lua_pushstring(L, shading::color_space_name(self(L).color));
  return 1;
}

int w_input_names(lua_State* L) {
  const Dataset& d = self(L);
  push_strings(L, d.input_names);
  return 1;
}

// ds:conditions() -> { {name =, min =, max =}, ... }: the inputs a conditioned dataset varies per row
int w_conditions(lua_State* L) {
  const Dataset& d = self(L);
  lua_createtable(L, int(d.conditions.size()), 0);
  for (std::size_t i = 0; i < d.conditions.size(); ++i) {
    lua_createtable(L, 0, 3);
    lua_pushstring(L, d.conditions[i].name.c_str()), lua_setfield(L, -2, "name");
    lua_pushnumber(L, d.conditions[i].min), lua_setfield(L, -2, "min");
    lua_pushnumber(L, d.conditions[i].max), lua_setfield(L, -2, "max");
    lua_rawseti(L, -2, int(i + 1));
  }
  return 1;
}

// ds:row("train" | "val", i) -> x, y (tables), for inspection
int w_row(lua_State* L) {
  const Dataset& d = self(L);
  const bool train = check_choice(check_string(L, 2, "dataset:row set"), {"train", "val"}, "dataset set") == 0;
  const std::size_t n = train ? d.train_count() : d.val_count();
  long long i = check_integer(L, 3, "dataset:row index");
  if (i < 1 || std::size_t(i) > n)
    throw Error("dataset:row: " + std::string(train ? "training" : "validation") + " row " + std::to_string(i) +
                " out of 1.." + std::to_string(n));
  const float* x = (train ? d.train_x : d.val_x).data() + std::size_t(i - 1) * d.inputs;
  const float* y = (train ? d.train_y : d.val_y).data() + std::size_t(i - 1) * d.outputs;
  for (auto [v, w] : {std::pair{x, d.inputs}, std::pair{y, d.outputs}}) {
    lua_createtable(L, w, 0);
    for (int k = 0; k < w; ++k) {
      lua_pushnumber(L, v[k]);
      lua_rawseti(L, -2, k + 1);
    }
  }
  return 2;
}

int w_tostring(lua_State* L) {
  auto* ud = static_cast<Box<Dataset>*>(test_type(L, 1, kType));
  if (!ud || !ud->ptr) {
    lua_pushstring(L, "Dataset (released)");
    return 1;
  }
  const Dataset& d = *ud->ptr;
  std::string s = "Dataset(" + std::to_string(d.inputs) + " -> " + std::to_string(d.outputs) + " " +
                  shading::color_space_name(d.color) + ", " + std::to_string(d.train_count()) + " train / " +
                  std::to_string(d.val_count()) + " val)";
  lua_pushstring(L, s.c_str());
  return 1;
}

// ---- combining, saving, loading (engine: data/combine.h, data/dataset_file.h) ----

// Runs f(); an engine error gets the Lua function's name in front.
template <class F>
auto named(const char* fn, F&& f) {
  try {
    return f();
  } catch (const std::exception& e) {
    throw Error(std::string(fn) + ": " + e.what());
  }
}

// sn.dataset.concat{ a, b, ... } -> Dataset
int w_concat(lua_State* L) {
  const char* fn = "sn.dataset.concat";
  if (!lua_istable(L, 1))
    throw Error(std::string(fn) + ": a list of Datasets expected ({a, b, ...}), got " + type_name_at(L, 1));
  const int n = check_list(L, 1, fn, "{a, b, ...}");
  if (n == 0) throw Error(std::string(fn) + ": the list is empty; give at least one Dataset");
  std::vector<std::shared_ptr<Dataset>> held;
  std::vector<const Dataset*> parts;
  for (int i = 1; i <= n; ++i) {
    lua_rawgeti(L, 1, i);
    auto* box = static_cast<Box<Dataset>*>(test_type(L, -1, kType));
    if (!box) throw Error(std::string(fn) + ": item " + std::to_string(i) + " is a " + type_name_at(L, -1) + ", Dataset expected");
    if (!box->ptr) throw Error(std::string(fn) + ": dataset " + std::to_string(i) + " was released; it can no longer be used");
    held.push_back(box->ptr);
    parts.push_back(box->ptr.get());
    lua_pop(L, 1);
  }
  push(L, named(fn, [&] { return data::concat(parts); }), kType);
  return 1;
}

// ds:subset{ count = n | fraction = f, seed = s, where = { input, axis, min, max } } -> Dataset
int w_subset(lua_State* L) {
  const char* fn = "dataset:subset";
  const Dataset& d = self(L);
  Options o(L, 2, fn, {"count", "fraction", "seed", "where"});
  data::SubsetRequest r;
  if (o.has("count")) {
    const long long c = o.integer("count");
    if (c < 1) throw Error(o.where("count") + " must be at least 1, got " + std::to_string(c));
    r.count = std::size_t(c);
  }
  if (o.has("fraction")) r.fraction = o.number("fraction");
  if (o.has("seed")) {
    const uint64_t s = o.seed("seed", 1);
    if (!r.count && !r.fraction) throw Error(o.where("seed") + " chooses the rows of count or fraction; give one of them");
    r.seed = s;
  }
  if (o.has("where")) {
    const int wi = o.push("where");
    Options w(L, wi, "dataset:subset option 'where'", {"input", "axis", "min", "max"});
    data::RowFilter f;
    f.input = w.string("input");
    const int ai = w.push("axis");
    if (lua_type(L, ai) == LUA_TSTRING) {
      const std::string a = lua_tostring(L, ai);
      const std::string letters = "xyzuv";
      const auto at = a.size() == 1 ? letters.find(a[0]) : std::string::npos;
      if (at == std::string::npos)
        throw Error(w.where("axis") + ": unknown axis '" + a + "' (valid: x, y, z, u, v or a 1-based index)");
      // u, v name uv's components 1, 2 as x, y (and z) name the others' ('u' of a normal was taken as x).
      if ((f.input == "uv") != (at >= 3))
        throw Error(w.where("axis") + ": input '" + f.input + "' has the axes " + (f.input == "uv" ? "u, v" : "x, y, z") +
                    " (or a 1-based index), not '" + a + "'");
      f.component = int(at % 3);
    } else if (lua_isnil(L, ai)) {
      throw Error(w.where("axis") + " is required (x, y, z, u, v or a 1-based index)");
    } else {
      f.component = check_int32(L, ai, w.where("axis").c_str()) - 1;
    }
    lua_pop(L, 1);
    if (!w.has("min") && !w.has("max")) throw Error("dataset:subset option 'where': give min, max or both");
    f.min = w.number("min", f.min);
    f.max = w.number("max", f.max);
    lua_pop(L, 1);
    r.where = f;
  }
  if (!r.count && !r.fraction && !r.where) throw Error(std::string(fn) + ": give count, fraction or where");
  push(L, named(fn, [&] { return data::subset(d, r); }), kType);
  return 1;
}

// ds:split{ split = 0.8, seed = 1 } -> Dataset
int w_split(lua_State* L) {
  const Dataset& d = self(L);
  if (lua_isnoneornil(L, 2)) {
    lua_settop(L, 1);
    lua_newtable(L);
  }
  Options o(L, 2, "dataset:split", {"split", "seed"});
  const double split = o.number("split", 0.8);
  const uint64_t seed = o.seed("seed", 1);
  push(L, named("dataset:split", [&] { return data::resplit(d, split, seed); }), kType);
  return 1;
}

// ds:export(path) -> the path to load it from (the sidecar or the CSV file)
int w_export(lua_State* L) {
  const Dataset& d = self(L);
  const std::string path = check_string(L, 2, "dataset:export path");
  const auto p = named("dataset:export", [&] { return data::export_dataset(d, path); });
  lua_pushstring(L, p.main.c_str());
  return 1;
}

// sn.dataset.load(path) -> Dataset
int w_load(lua_State* L) {
  const std::string path = check_string(L, 1, "sn.dataset.load path");
  push(L, named("sn.dataset.load", [&] { return data::load_dataset(path); }), kType);
  return 1;
}

// sn.dataset.attributes() -> the G-buffer attributes a dataset's inputs may name, in the
// runtime's one list (scripts check names against it before building anything)
int w_attributes(lua_State* L) {
  push_strings(L, scene::gbuffer_attribute_names());
  return 1;
}

}  // namespace

void open_dataset(lua_State* L) {
  static const luaL_Reg methods[] = {SN_FN("counts", w_counts),   SN_FN("inputs", w_inputs),
                                     SN_FN("outputs", w_outputs), SN_FN("color", w_color),
                                     SN_FN("input_names", w_input_names), SN_FN("conditions", w_conditions), SN_FN("row", w_row),
                                     SN_FN("subset", w_subset), SN_FN("split", w_split), SN_FN("export", w_export),
                                     SN_FN("coverage", dataset_coverage),
                                     {nullptr, nullptr}};
  define_box_type<Dataset>(L, kType, methods, wrap<w_tostring>);
  // sn.dataset is a table of dataset functions that is also callable: sn.dataset{...} makes one.
  lua_newtable(L);
  lua_createtable(L, 0, 1);
  lua_pushcfunction(L, wrap<w_call>);
  lua_setfield(L, -2, "__call");
  lua_setmetatable(L, -2);
  lua_pushcfunction(L, wrap<w_concat>);
  lua_setfield(L, -2, "concat");
  lua_pushcfunction(L, wrap<w_load>);
  lua_setfield(L, -2, "load");
  lua_pushcfunction(L, wrap<w_attributes>);
  lua_setfield(L, -2, "attributes");
  lua_setfield(L, -2, "dataset");
}

}  // namespace sn::lua

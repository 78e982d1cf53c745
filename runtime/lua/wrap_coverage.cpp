// ds:coverage{...}: which normal and view bins a dataset's rows fill, how much of another
// dataset or a scene falls outside them, and the figure of both (engine: data/coverage.h).
#include <memory>
#include <stdexcept>

#include "data/coverage.h"
#include "io/image.h"
#include "lua/binding.h"
#include "lua/lua_scene.h"
#include "lua/module.h"

namespace sn::lua {

namespace {

constexpr const char* kWhat = "ds:coverage";

void set_number(lua_State* L, const char* key, double v) {
  lua_pushnumber(L, v);
  lua_setfield(L, -2, key);
}

void push_bins(lua_State* L, const std::vector<uint32_t>& counts, int bands, int sectors, int min_count) {
  const std::size_t covered = data::covered_bins(counts, min_count);
  lua_createtable(L, 0, 6);
  set_number(L, "bins", double(counts.size()));
  set_number(L, "bands", bands);
  set_number(L, "sectors", sectors);
  set_number(L, "covered", double(covered));
  set_number(L, "fraction", double(covered) / double(counts.size()));
}

int divisions(const Options& o, const char* key, int def) {
  const long long v = o.integer(key, def);
  if (v < 1 || v > data::kMaxDivisions)
    throw Error(o.where(key) + " must be 1.." + std::to_string(data::kMaxDivisions) + ", got " + std::to_string(v));
  return int(v);
}

}  // namespace

// ds:coverage{ min_count = 1, against = Dataset | Scene, figure = "out/coverage.png", title = "...",
//              normal_bands = 16, normal_sectors = 32, view_bands = 8, view_sectors = 32 } -> table
int dataset_coverage(lua_State* L) {
  const data::Dataset& d = check<data::Dataset>(L, 1, "Dataset");
  if (lua_isnoneornil(L, 2)) {
    lua_settop(L, 1);
    lua_newtable(L);
  }
  Options o(L, 2, kWhat,
            {"min_count", "against", "figure", "title", "normal_bands", "normal_sectors", "view_bands", "view_sectors"});
  const long long min_count = o.integer("min_count", 1);
  if (min_count < 1 || min_count > (1ll << 31))
    throw Error(o.where("min_count") + " must be at least 1 (rows a bin needs to count as covered), got " +
                std::to_string(min_count));
  data::BinScheme scheme;
  scheme.normal_bands = divisions(o, "normal_bands", scheme.normal_bands);
  scheme.normal_sectors = divisions(o, "normal_sectors", scheme.normal_sectors);
  scheme.view_bands = divisions(o, "view_bands", scheme.view_bands);
  scheme.view_sectors = divisions(o, "view_sectors", scheme.view_sectors);
  const std::string figure = o.string("figure", "");
  if (o.has("figure") && figure.empty()) throw Error(o.where("figure") + ": a file path expected, got an empty string");
  const std::string title_opt = o.string("title", "");
  if (o.has("title") && figure.empty()) throw Error(o.where("title") + " labels the figure: give 'figure' too");

  const data::Histogram mine = data::histogram(data::dataset_directions(d, kWhat), scheme);

  // The other rows: a dataset's, or a scene's covered pixels (kept alive in `scene_rows`).
  std::vector<data::DirectionRows> other_rows;
  std::vector<float> scene_rows;
  std::string against_name;
  const int ai = o.push("against");
  if (!lua_isnil(L, ai)) {
    if (test_type(L, ai, "Dataset")) {
      other_rows = data::dataset_directions(check<data::Dataset>(L, ai, "Dataset"), o.where("against"));
      against_name = "the other dataset";
    } else if (test_type(L, ai, kSceneType)) {
      const LuaScene& s = check<LuaScene>(L, ai, kSceneType);
      try {
        scene_rows = data::scene_directions(s.scene);
      } catch (const std::invalid_argument& e) {
        throw Error(o.where("against") + ": " + e.what());
      }
      other_rows.push_back({scene_rows.data(), scene_rows.data() + 3, 6, scene_rows.size() / 6});
      std::string names;
      for (const auto& m : s.scene.meshes) names += (names.empty() ? "" : ", ") + m.mesh->name;
      against_name = "the scene (" + names + ")";
    } else {
      throw Error(o.where("against") + ": a Dataset or a Scene expected, got " + type_name_at(L, ai));
    }
  }
  lua_pop(L, 1);
  const bool against = !against_name.empty();
  data::Outside out;
  std::unique_ptr<data::Histogram> other;
  if (against) {
    out = data::outside(mine, int(min_count), other_rows);
    if (!figure.empty()) other = std::make_unique<data::Histogram>(data::histogram(other_rows, scheme));
  }

  if (!figure.empty()) {
    data::CoverageFigure f;
    f.min_count = int(min_count);
    f.against = against_name;
    f.title = !title_opt.empty() ? title_opt
                                 : "coverage of a dataset of " + std::to_string(mine.rows) + " rows" +
                                       (against ? " against " + against_name : "");
    try {
      io::save_image(data::coverage_figure(mine, other.get(), f), figure);
    } catch (const std::exception& e) {
      throw Error(o.where("figure") + ": " + e.what());
    }
  }

  lua_createtable(L, 0, 12);
  set_number(L, "rows", double(mine.rows));
  set_number(L, "invalid", double(mine.invalid));
  set_number(L, "non_unit", double(mine.non_unit));
  set_number(L, "min_count", double(min_count));
  push_bins(L, mine.normal, scheme.normal_bands, scheme.normal_sectors, int(min_count));
  set_number(L, "y_min", mine.normal_y_min);
  set_number(L, "y_max", mine.normal_y_max);
  lua_setfield(L, -2, "normal");
  push_bins(L, mine.view, scheme.view_bands, scheme.view_sectors, int(min_count));
  set_number(L, "below_horizon", double(mine.below_horizon));
  lua_setfield(L, -2, "view");
  lua_pushstring(L, scheme.text().c_str());
  lua_setfield(L, -2, "scheme");
  if (against) {
    set_number(L, "against_rows", double(out.rows));
    lua_createtable(L, 0, 3);
    set_number(L, "normal", out.normal);
    set_number(L, "view", out.view);
    set_number(L, "either", out.either);
    lua_setfield(L, -2, "outside");
  }
  if (!figure.empty()) {
    lua_pushstring(L, figure.c_str());
    lua_setfield(L, -2, "figure");
  }
  return 1;
}

}  // namespace sn::lua

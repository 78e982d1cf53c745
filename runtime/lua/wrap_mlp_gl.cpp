// The GPU side of the "Mlp" type: net:forward(samples) in a compute shader and net:render(gbuffer)
// in a fragment shader, added to the methods open_mlp defined; and the "gl" training backend,
// registered for sn.train.
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <vector>

#include "gl/buffer.h"
#include "gl/render_target.h"
#include "io/image.h"
#include "io/text.h"
#include "lua/binding.h"
#include "lua/mlp_binding.h"
#include "lua/module.h"
#include "data/dataset.h"
#include "nn/gl_forward.h"
#include "nn/mlp_render.h"
#include "nn/render.h"
#include "nn/render_errors.h"
#include "nn/trainer.h"
#include "scene/gbuffer.h"

namespace sn::lua {

namespace {

constexpr const char* kType = "Mlp";
using nn::Mlp;

// One sample (a table of numbers) or many (a table of such tables) -> rows x inputs floats.
std::vector<float> rows_from_table(lua_State* L, int idx, int inputs, bool* nested) {
  const int n = check_list(L, idx, "net:forward");
  if (n == 0) throw Error("net:forward: the table holds no samples");
  lua_rawgeti(L, idx, 1);
  *nested = lua_istable(L, -1);
  lua_pop(L, 1);
  std::vector<float> x;
  auto read_row = [&](int t, const std::string& what) {
    auto v = check_numbers(L, t, what.c_str(), inputs);
    for (std::size_t i = 0; i < v.size(); ++i) {
      // As float, the kernels' type: 1e39 would pass as a double and run as infinity.
      if (!std::isfinite(float(v[i])))
        throw Error(what + " input " + std::to_string(i + 1) + " is " + io::number_text(v[i]) +
                    (std::isfinite(v[i]) ? ", beyond float's range (3.4e38)" : "") + ": values must be finite floats");
      x.push_back(float(v[i]));
    }
  };
  if (!*nested) {
    read_row(idx, "net:forward sample");
  } else {
    for (int r = 1; r <= n; ++r) {
      lua_rawgeti(L, idx, r);
      read_row(lua_gettop(L), "net:forward sample " + std::to_string(r));
      lua_pop(L, 1);
    }
  }
  return x;
}

// What net:forward and net:render do with outputs that are NaN or infinite (a diverged network,
// weights that overflow): `nonfinite = "warn"` (default: one line on stderr, once per network
// version), "error", or "ignore".
enum class NonFinite { warn, error, ignore };

NonFinite read_nonfinite(lua_State* L, int idx, const char* what) {
  if (lua_isnoneornil(L, idx)) return NonFinite::warn;
  Options o(L, idx, what, {"nonfinite"});
  return NonFinite(o.choice("nonfinite", {"warn", "error", "ignore"}, 0));
}

void report_nonfinite(const std::shared_ptr<Mlp>& net, const char* what, std::size_t bad, std::size_t total,
                      const char* unit, const std::string& first, NonFinite mode) {
  if (bad == 0 || mode == NonFinite::ignore) return;
  const std::string msg = std::string(what) + ": " + std::to_string(bad) + " of " + std::to_string(total) + " " + unit +
                          " are NaN or infinite" + (first.empty() ? "" : " (the first: " + first + ")") + "; the weights of " + net->spec.describe() +
                          " may have diverged";
  if (mode == NonFinite::error) throw Error(msg);
  // Once per network version and caller: a live view renders the same network every frame.
  struct Warned {
    std::weak_ptr<Mlp> net;
    uint64_t version;
    std::string what;
  };
  static std::vector<Warned> warned;
  std::erase_if(warned, [](const Warned& w) { return w.net.expired(); });
  for (const Warned& w : warned)
    if (w.net.lock() == net && w.version == net->version && w.what == what) return;
  warned.push_back({net, net->version, what});
  std::fprintf(stderr, "warning: %s (nonfinite = \"error\" makes this an error, \"ignore\" silences it)\n", msg.c_str());
}

// Counts the non-finite values of rows x outputs floats.
void check_outputs(const std::shared_ptr<Mlp>& net, const float* y, std::size_t n, NonFinite mode) {
  if (mode == NonFinite::ignore) return;
  const std::size_t outputs = std::size_t(net->spec.outputs);
  std::size_t bad = 0, first = 0;
  for (std::size_t j = 0; j < n; ++j)
    if (!std::isfinite(y[j]) && bad++ == 0) first = j;
  report_nonfinite(net, "net:forward", bad, n, "outputs",
                   "row " + std::to_string(first / outputs + 1) + " output " + std::to_string(first % outputs + 1), mode);
}

void push_row(lua_State* L, const float* y, int n) {
  lua_createtable(L, n, 0);
  for (int i = 0; i < n; ++i) {
    lua_pushnumber(L, y[i]);
    lua_rawseti(L, -2, i + 1);
  }
}

// net:forward(x [, { nonfinite = "warn" | "error" | "ignore" }]) evaluates the network in a
// compute shader:
//   x a float32 Buffer of rows x inputs numbers -> a float32 Buffer of rows x outputs;
//   x a Dataset [, "val" (default) | "train"]   -> a float32 Buffer of that set's outputs;
//   x a table of inputs numbers (one sample)    -> a table of outputs numbers;
//   x a table of such tables                    -> a table of tables.
// Outputs that are NaN or infinite are counted: a warning (default), an error or nothing.
int w_forward(lua_State* L) {
  auto net = check_shared<Mlp>(L, 1, kType);
  const int in = net->spec.inputs, out = net->spec.outputs;
  // The options follow x (and a dataset's set name).
  const int opt = test_type(L, 2, "Dataset") && lua_type(L, 3) == LUA_TSTRING ? 4 : 3;
  const NonFinite mode = read_nonfinite(L, opt, "net:forward");
  auto checked = [&](std::shared_ptr<gl::Buffer> y) {
    if (mode != NonFinite::ignore) {
      const std::vector<float> v = y->download_floats();
      check_outputs(net, v.data(), v.size(), mode);
    }
    return y;
  };
  if (test_type(L, 2, "Buffer")) {
    gl::Buffer& x = check<gl::Buffer>(L, 2, "Buffer");
    if (!gl::elem_info(x.type()).is_float) throw Error("net:forward: the buffer must hold floats, got " + std::string(gl::elem_info(x.type()).name));
    if (x.components() % std::size_t(in))
      throw Error("net:forward: the buffer's " + std::to_string(x.components()) + " numbers are not whole rows of " +
                  std::to_string(in) + " inputs");
    // Checked on the host before any GPU work, as tables and datasets are: a NaN input would
    // come back as a NaN output with nothing saying where it came from.
    const std::vector<float> v = x.download_floats();
    for (std::size_t j = 0; j < v.size(); ++j)
      if (!std::isfinite(v[j]))
        throw Error("net:forward: buffer row " + std::to_string(j / std::size_t(in) + 1) + " input " +
                    std::to_string(j % std::size_t(in) + 1) + " is " + (std::isnan(v[j]) ? "NaN" : "infinite"));
    push(L, checked(nn::gl_forward(*net, x, x.components() / std::size_t(in))), "Buffer");
    return 1;
  }
  if (test_type(L, 2, "Dataset")) {
    const data::Dataset& d = check<data::Dataset>(L, 2, "Dataset");
    const bool train = opt == 3 ? false
                                : check_choice(check_string(L, 3, "net:forward set"), {"val", "train"}, "dataset set") == 1;
    if (d.inputs != in)
      throw Error("net:forward: the dataset has " + std::to_string(d.inputs) + " inputs, " + net->spec.describe() +
                  " takes " + std::to_string(in));
    const std::vector<float>& x = train ? d.train_x : d.val_x;
    if (x.empty()) throw Error(std::string("net:forward: the dataset's ") + (train ? "train" : "val") + " set is empty");
    gl::Buffer xb(gl::ElemType::float32, x.size());
    xb.upload(x.data(), 0, x.size());
    push(L, checked(nn::gl_forward(*net, xb, x.size() / std::size_t(in))), "Buffer");
    return 1;
  }
  if (lua_istable(L, 2)) {
    bool nested = false;
    auto x = rows_from_table(L, 2, in, &nested);
    auto y = nn::gl_forward(*net, x);
    check_outputs(net, y.data(), y.size(), mode);
    if (!nested) {
      push_row(L, y.data(), out);
    } else {
      const int rows = int(x.size() / std::size_t(in));
      lua_createtable(L, rows, 0);
      for (int r = 0; r < rows; ++r) {
        push_row(L, y.data() + std::size_t(r) * std::size_t(out), out);
        lua_rawseti(L, -2, r + 1);
      }
    }
    return 1;
  }
  throw Error("net:forward: a Buffer, a Dataset or a table of samples expected, got " + type_name_at(L, 2));
}

// What the last net:render did, for sn.render_info().
struct LastRender {
  std::string backend, reason;
  std::size_t nonfinite = 0;
  bool counted = false, timed = false;
  nn::CpuRenderTimes times;
};
LastRender& last_render() {
  static LastRender r;
  return r;
}

// net:render(gbuffer [, { backend = "auto", frames = 1, weights = "auto", values = { condition = x },
//                         target = Target, nonfinite = "warn" | "error" | "ignore" }])
//   -> Image (RGBA float); with `target`: that Target
// The network as the lighting model of every covered pixel, reading the G-buffer attributes
// named by net:inputs() and, for a conditioned network, each condition's value from `values`
// (else net:conditions()[k].value); alpha = coverage. `backend`: "gl" (fragment shader), "cpu"
// (the cpu kernels over the covered pixels) or "auto" (nn/render.h). `frames` renders it that
// many times first (for timing; the image is the last); `weights = "storage"` reads the
// parameters from a storage buffer even where a uniform buffer would hold them (gl only).
// `target` (the G-buffer's size) receives the render in attachment 1 instead of a new Image: no
// read-back (what a window shows). Covered pixels with a NaN or infinite value are counted and
// reported as net:forward reports outputs (`nonfinite`); gl drawing into a target reads nothing
// back, so it counts nothing.
// sn.render_info() says which backend drew it and why (one return value, so that
// f(net:render(g)) composes).
int w_render(lua_State* L) {
  auto net = check_shared<Mlp>(L, 1, kType);
  const scene::GBuffer& g = check<scene::GBuffer>(L, 2, "GBuffer");
  nn::RenderOptions ro;
  int target_at = 0;  // stack index of the `target` option
  NonFinite mode = NonFinite::warn;
  if (!lua_isnoneornil(L, 3)) {
    Options o(L, 3, "net:render", {"backend", "frames", "weights", "values", "target", "nonfinite"});
    mode = NonFinite(o.choice("nonfinite", {"warn", "error", "ignore"}, 0));
    if (o.has("values")) {
      int vi = o.push("values");
      if (!lua_istable(L, vi)) throw Error(o.where("values") + ": { condition = number, ... } expected");
      lua_pushnil(L);
      while (lua_next(L, vi)) {
        std::string name = lua_type(L, -2) == LUA_TSTRING ? lua_tostring(L, -2) : "?";
        double v = check_number(L, -1, (o.where("values") + " '" + name + "'").c_str());
        const nn::Condition* c = net->condition(name);
        if (c)
          if (std::string why = nn::condition_value_problem(*c, v); !why.empty()) throw Error(o.where("values") + ": " + why);
        ro.values[name] = v;
        lua_pop(L, 1);
      }
      lua_pop(L, 1);
    }
    long long f = o.integer("frames", 1);
    if (f < 1 || f > 100000) throw Error("net:render option 'frames' must be 1..100000, got " + std::to_string(f));
    ro.frames = int(f);
    if (o.choice("weights", {"auto", "storage"}, 0) == 1) ro.weights = nn::WeightBuffer::storage;
    ro.backend = nn::RenderBackend(o.choice("backend", {"auto", "gl", "cpu"}, 0));
    if (o.has("target")) {
      const int ti = o.push("target");
      if (!test_type(L, ti, "Target")) throw Error(o.where("target") + ": Target expected, got " + type_name_at(L, ti));
      target_at = ti;
    }
  }
  nn::Rendered r;
  if (target_at) {
    r = nn::render_network(net, g, check<gl::RenderTarget>(L, target_at, "Target"), ro);
    lua_pushvalue(L, target_at);
  } else {
    r = nn::render_network(net, g, ro);
    push(L, std::make_shared<io::Image>(std::move(r.image)), "Image");
  }
  const bool counted = !(target_at && r.backend == nn::RenderBackend::gl);
  last_render() = LastRender{nn::render_backend_name(r.backend), r.reason, r.nonfinite, counted,
                             r.backend == nn::RenderBackend::cpu, r.cpu_times};
  if (counted && r.nonfinite) {
    std::string first;  // where the first one is, when the image is on the host
    if (!target_at) {
      const io::Image& img = check<io::Image>(L, -1, "Image");
      const float* p = img.pixels.data();
      for (std::size_t i = 0; first.empty() && i < img.pixels.size(); i += 4)
        if (p[i + 3] > 0.0f && !(std::isfinite(p[i]) && std::isfinite(p[i + 1]) && std::isfinite(p[i + 2])))
          first = "pixel (" + std::to_string(i / 4 % std::size_t(img.width)) + ", " +
                  std::to_string(i / 4 / std::size_t(img.width)) + ")";
    }
    report_nonfinite(net, "net:render", r.nonfinite, std::size_t(g.width) * std::size_t(g.height), "pixels", first,
                     mode);
  }
  return 1;
}

// sn.render_errors{ nets = {net, ...} | net, views = { {gbuffer = G, truth = Image}, ... },
//                   nonfinite = "warn" | "error" | "ignore" }
//   -> errors[i][k] = { mse, ssim, nonfinite } of nets[i] rendered over views[k].gbuffer, clamped
// to [0, 1], against views[k].truth (RGBA, alpha = the covered pixels compared): what
// net:render, sn.image.clamp, sn.image.mse and sn.image.ssim give one at a time, for many
// networks at once on every thread (nn/render_errors.h). NaN or infinite pixels are reported
// as net:render reports them.
int w_render_errors(lua_State* L) {
  Options o(L, 1, "sn.render_errors", {"nets", "views", "nonfinite"});
  const NonFinite mode = NonFinite(o.choice("nonfinite", {"warn", "error", "ignore"}, 0));
  const std::vector<std::shared_ptr<Mlp>> nets = check_mlp_list(L, o.push("nets"), o.where("nets"));
  const int vi = o.push("views");  // stays on the stack: its G-buffers and images stay alive
  if (!lua_istable(L, vi)) throw Error(o.where("views") + ": a table of { gbuffer = G, truth = Image } expected");
  std::vector<nn::TruthView> views;
  const int nviews = check_list(L, vi, o.where("views"));
  for (int k = 1; k <= nviews; ++k) {
    lua_rawgeti(L, vi, k);
    const std::string where = o.where("views") + " element " + std::to_string(k);
    if (!lua_istable(L, -1)) throw Error(where + ": { gbuffer = G, truth = Image } expected, got " + type_name_at(L, -1));
    lua_getfield(L, -1, "gbuffer");
    if (!test_type(L, -1, "GBuffer")) throw Error(where + ": 'gbuffer' must be a GBuffer, got " + type_name_at(L, -1));
    const scene::GBuffer* g = &check<scene::GBuffer>(L, -1, "GBuffer");
    lua_getfield(L, -2, "truth");
    if (!test_type(L, -1, "Image")) throw Error(where + ": 'truth' must be an Image, got " + type_name_at(L, -1));
    views.push_back({g, &check<io::Image>(L, -1, "Image")});
    lua_pop(L, 3);
  }
  const std::vector<nn::RenderError> e = nn::render_errors({nets.begin(), nets.end()}, views);
  std::size_t pixels = 0;  // of all views: what a network's nonfinite count is out of
  for (const auto& v : views) pixels += std::size_t(v.gbuffer->width) * std::size_t(v.gbuffer->height);
  lua_createtable(L, int(nets.size()), 0);
  for (std::size_t i = 0; i < nets.size(); ++i) {
    std::size_t bad = 0;
    lua_createtable(L, int(views.size()), 0);
    for (std::size_t k = 0; k < views.size(); ++k) {
      const nn::RenderError& r = e[i * views.size() + k];
      bad += r.nonfinite;
      lua_createtable(L, 0, 3);
      lua_pushnumber(L, r.mse), lua_setfield(L, -2, "mse");
      lua_pushnumber(L, r.ssim), lua_setfield(L, -2, "ssim");
      lua_pushinteger(L, lua_Integer(r.nonfinite)), lua_setfield(L, -2, "nonfinite");
      lua_rawseti(L, -2, int(k + 1));
    }
    lua_rawseti(L, -2, int(i + 1));
    report_nonfinite(nets[i], "sn.render_errors", bad, pixels, "pixels", "", mode);
  }
  return 1;
}

// sn.render_info() -> { backend = "gl" | "cpu", reason = why that one, nonfinite = covered pixels
// that came out NaN or infinite (absent when gl drew into a target: nothing was read back),
// read_ms, network_ms = the cpu backend's time by stage } of the last net:render (nil before one).
int w_render_info(lua_State* L) {
  const LastRender& r = last_render();
  if (r.backend.empty()) return lua_pushnil(L), 1;
  lua_createtable(L, 0, 5);
  lua_pushstring(L, r.backend.c_str());
  lua_setfield(L, -2, "backend");
  lua_pushstring(L, r.reason.c_str());
  lua_setfield(L, -2, "reason");
  if (r.counted) {
    lua_pushinteger(L, lua_Integer(r.nonfinite));
    lua_setfield(L, -2, "nonfinite");
  }
  if (r.timed) {
    lua_pushnumber(L, r.times.read * 1e3);
    lua_setfield(L, -2, "read_ms");
    lua_pushnumber(L, r.times.network * 1e3);
    lua_setfield(L, -2, "network_ms");
  }
  return 1;
}

// sn.mlp_weight_uploads() -> parameter uploads by net:render so far (an unchanged network is not
// uploaded again).
int w_weight_uploads(lua_State* L) {
  lua_pushinteger(L, lua_Integer(nn::mlp_weight_uploads()));
  return 1;
}

}  // namespace

void open_mlp_gl(lua_State* L) {
  nn::register_backend("gl", nn::make_gl_backend);
  luaL_getmetatable(L, kType);
  if (!lua_istable(L, -1)) luaL_error(L, "internal: open_mlp_gl must run after open_mlp");
  lua_getfield(L, -1, "__methods");
  lua_pushcfunction(L, wrap<w_forward>);
  lua_setfield(L, -2, "forward");
  lua_pushcfunction(L, wrap<w_render>);
  lua_setfield(L, -2, "render");
  lua_pop(L, 2);
  lua_pushcfunction(L, wrap<w_weight_uploads>);
  lua_setfield(L, -2, "mlp_weight_uploads");
  lua_pushcfunction(L, wrap<w_render_info>);
  lua_setfield(L, -2, "render_info");
  lua_pushcfunction(L, wrap<w_render_errors>);
  lua_setfield(L, -2, "render_errors");
}

}  // namespace sn::lua

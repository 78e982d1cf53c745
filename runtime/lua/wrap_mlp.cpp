// sn.mlp{...}, sn.load(path) and the "Mlp" type: networks as scripts see them. Weights are read
// and edited through views (net.layers[i].weight[r][c], .bias[r]) that name the layer in every
// error; each edit bumps net:version() so the renderer re-uploads.
//
// Other bindings add methods to Mlp (e.g. the gl side's net:forward) by setting fields of the
// table in the metatable's "__methods" field; lookups go through it at call time.
#include <cmath>
#include <memory>

#include "io/text.h"
#include "lua/binding.h"
#include "lua/mlp_binding.h"
#include "lua/encoding_binding.h"
#include "lua/module.h"
#include "nn/checkpoint.h"
#include "nn/mlp.h"

namespace sn::lua {

namespace {

constexpr const char* kType = "Mlp";
constexpr const char* kView = "MlpView";
using nn::Mlp;

Mlp& self(lua_State* L) { return check<Mlp>(L, 1, kType); }

// A view onto part of a network. It holds the network weakly: after net:release() the views
// report that, instead of keeping a released network alive. Until then the view's environment
// table holds the network's Lua value, so that `sn.mlp{...}.layers[1].weight` keeps its network
// from the collector.
struct View {
  enum Kind { kLayers, kLayer, kWeight, kRow, kBias } kind;
  std::weak_ptr<Mlp> net;
  int layer = 0, row = 0;  // 0-based
};

const char* kKinds[] = {"layers", "layer", "weight", "weight row", "bias"};

// Pushes view v of the network at stack index `net`, or (view true) of the network a view there shows.
void push_view(lua_State* L, View v, int owner, bool view) {
  push(L, std::make_shared<View>(std::move(v)), kView);
  if (view) {
    lua_getfenv(L, owner);
  } else {
    lua_createtable(L, 1, 0);
    lua_pushvalue(L, owner);
    lua_rawseti(L, -2, 1);
  }
  lua_setfenv(L, -2);
}

std::shared_ptr<Mlp> net_of(const View& v) {
  auto p = v.net.lock();
  if (!p) throw Error("this Mlp was released; its layers can no longer be used");
  return p;
}

std::string layer_name(const View& v) { return "layer " + std::to_string(v.layer + 1); }

int check_index(lua_State* L, int idx, int n, const std::string& what) {
  if (lua_type(L, idx) != LUA_TNUMBER) throw Error(what + " index must be a number, got " + type_name_at(L, idx));
  double d = lua_tonumber(L, idx);
  if (d != std::floor(d) || d < 1 || d > n) {
    char buf[64];
    snprintf(buf, sizeof buf, "%g", d);
    throw Error(what + " " + buf + " out of 1.." + std::to_string(n));
  }
  return int(d) - 1;
}

float check_weight(lua_State* L, int idx, const std::string& what) {
  if (lua_type(L, idx) != LUA_TNUMBER) throw Error(what + " must be a number, got " + type_name_at(L, idx));
  double v = lua_tonumber(L, idx);
  if (!std::isfinite(v) || !std::isfinite(float(v))) throw Error(what + " must be a finite float, got " + io::number_text(v));
  return float(v);
}

// A Lua array of `n` finite numbers into out[0..n).
void read_vector(lua_State* L, int idx, int n, float* out, const std::string& what) {
  idx = absindex(L, idx);
  if (!lua_istable(L, idx)) throw Error(what + ": table of " + std::to_string(n) + " numbers expected, got " + type_name_at(L, idx));
  const int len = check_list(L, idx, what);
  if (len != n) throw Error(what + ": " + std::to_string(n) + " numbers expected, got " + std::to_string(len));
  for (int i = 0; i < n; ++i) {
    lua_rawgeti(L, idx, i + 1);
    out[i] = check_weight(L, -1, what + "[" + std::to_string(i + 1) + "]");
    lua_pop(L, 1);
  }
}

void push_vector(lua_State* L, const float* v, int n) {
  lua_createtable(L, n, 0);
  for (int i = 0; i < n; ++i) {
    lua_pushnumber(L, v[i]);
    lua_rawseti(L, -2, i + 1);
  }
}

// Whole-layer weights: `out` rows of `in` numbers.
void read_matrix(lua_State* L, int idx, Mlp& net, int l, const std::string& what) {
  const int in = net.spec.width(l), out = net.spec.width(l + 1);
  idx = absindex(L, idx);
  if (!lua_istable(L, idx)) throw Error(what + ": table of " + std::to_string(out) + " rows expected, got " + type_name_at(L, idx));
  const int len = check_list(L, idx, what);
  if (len != out)
    throw Error(what + ": " + std::to_string(out) + " rows of " + std::to_string(in) + " expected, got " + std::to_string(len) + " rows");
  std::vector<float> w(std::size_t(in) * out);
  for (int r = 0; r < out; ++r) {
    lua_rawgeti(L, idx, r + 1);
    read_vector(L, -1, in, &w[std::size_t(r) * in], what + " row " + std::to_string(r + 1));
    lua_pop(L, 1);
  }
  std::copy(w.begin(), w.end(), net.weights(l));
}

void push_matrix(lua_State* L, const Mlp& net, int l) {
  const int in = net.spec.width(l), out = net.spec.width(l + 1);
  lua_createtable(L, out, 0);
  for (int r = 0; r < out; ++r) {
    push_vector(L, net.weights(l) + std::size_t(r) * in, in);
    lua_rawseti(L, -2, r + 1);
  }
}

// ---- views ----

int w_view_index(lua_State* L) {
  const View& v = check<View>(L, 1, kView);
  auto net = net_of(v);
  const bool name = lua_type(L, 2) == LUA_TSTRING;
  const std::string key = name ? lua_tostring(L, 2) : "";
  if (name && key == "table") {  // :table() -> plain Lua copy of what the view shows
    lua_pushvalue(L, lua_upvalueindex(1));
    return 1;
  }
  switch (v.kind) {
    case View::kLayers: {
      int l = check_index(L, 2, net->spec.layers(), "layer");
      push_view(L, {View::kLayer, v.net, l, 0}, 1, true);
      return 1;
    }
    case View::kLayer: {
      const int in = net->spec.width(v.layer), out = net->spec.width(v.layer + 1);
      if (key == "weight") push_view(L, {View::kWeight, v.net, v.layer, 0}, 1, true);
      else if (key == "bias") push_view(L, {View::kBias, v.net, v.layer, 0}, 1, true);
      else if (key == "inputs") lua_pushinteger(L, in);
      else if (key == "outputs") lua_pushinteger(L, out);
      else if (key == "activation")
        lua_pushstring(L, nn::activation_name(v.layer + 1 == net->spec.layers() ? net->spec.output_activation
                                                                                : net->spec.activation));
      else throw Error(layer_name(v) + ": no field '" + (name ? key : type_name_at(L, 2)) +
                       "' (valid: weight, bias, inputs, outputs, activation)");
      return 1;
    }
    case View::kWeight: {
      int r = check_index(L, 2, net->spec.width(v.layer + 1), layer_name(v) + ": weight row");
      push_view(L, {View::kRow, v.net, v.layer, r}, 1, true);
      return 1;
    }
    case View::kRow: {
      const int in = net->spec.width(v.layer);
      int c = check_index(L, 2, in, layer_name(v) + ": weight[" + std::to_string(v.row + 1) + "] column");
      lua_pushnumber(L, net->weights(v.layer)[std::size_t(v.row) * in + c]);
      return 1;
    }
    case View::kBias: {
      int r = check_index(L, 2, net->spec.width(v.layer + 1), layer_name(v) + ": bias index");
      lua_pushnumber(L, net->biases(v.layer)[r]);
      return 1;
    }
  }
  return 0;
}

int w_view_newindex(lua_State* L) {
  const View& v = check<View>(L, 1, kView);
  auto net = net_of(v);
  const int in = net->spec.width(v.layer), out = net->spec.width(v.layer + 1);
  const std::string who = layer_name(v);
  switch (v.kind) {
    case View::kLayers:
      throw Error("net.layers cannot be replaced; set net.layers[i].weight or .bias instead");
    case View::kLayer: {
      const std::string key = lua_type(L, 2) == LUA_TSTRING ? lua_tostring(L, 2) : "";
      if (key == "weight") read_matrix(L, 3, *net, v.layer, who + ": weight");
      else if (key == "bias") read_vector(L, 3, out, net->biases(v.layer), who + ": bias");
      else throw Error(who + ": cannot set '" + (key.empty() ? type_name_at(L, 2) : key) + "' (settable: weight, bias)");
      break;
    }
    case View::kWeight: {
      int r = check_index(L, 2, out, who + ": weight row");
      std::vector<float> row(static_cast<std::size_t>(in));
      read_vector(L, 3, in, row.data(), who + ": weight row " + std::to_string(r + 1));
      std::copy(row.begin(), row.end(), net->weights(v.layer) + std::size_t(r) * in);
      break;
    }
    case View::kRow: {
      int c = check_index(L, 2, in, who + ": weight[" + std::to_string(v.row + 1) + "] column");
      net->weights(v.layer)[std::size_t(v.row) * in + c] =
          check_weight(L, 3, who + ": weight[" + std::to_string(v.row + 1) + "][" + std::to_string(c + 1) + "]");
      break;
    }
    case View::kBias: {
      int r = check_index(L, 2, out, who + ": bias index");
      net->biases(v.layer)[r] = check_weight(L, 3, who + ": bias[" + std::to_string(r + 1) + "]");
      break;
    }
  }
  net->touch();
  return 0;
}

int w_view_len(lua_State* L) {
  const View& v = check<View>(L, 1, kView);
  auto net = net_of(v);
  int n = 0;
  switch (v.kind) {
    case View::kLayers: n = net->spec.layers(); break;
    case View::kLayer: n = 0; break;
    case View::kWeight:
    case View::kBias: n = net->spec.width(v.layer + 1); break;
    case View::kRow: n = net->spec.width(v.layer); break;
  }
  lua_pushinteger(L, n);
  return 1;
}

// view:table(): a plain copy (weight -> rows of numbers, row/bias -> numbers).
int w_view_table(lua_State* L) {
  const View& v = check<View>(L, 1, kView);
  auto net = net_of(v);
  const int in = net->spec.width(v.layer), out = net->spec.width(v.layer + 1);
  switch (v.kind) {
    case View::kWeight: push_matrix(L, *net, v.layer); break;
    case View::kRow: push_vector(L, net->weights(v.layer) + std::size_t(v.row) * in, in); break;
    case View::kBias: push_vector(L, net->biases(v.layer), out); break;
    default: throw Error(std::string("net.") + kKinds[v.kind] + " has no :table(); use .weight:table() or .bias:table()");
  }
  return 1;
}

int w_view_tostring(lua_State* L) {
  auto* ud = static_cast<Box<View>*>(test_type(L, 1, kView));
  auto net = ud && ud->ptr ? ud->ptr->net.lock() : nullptr;
  if (!net) {
    lua_pushstring(L, "MlpView (released)");
    return 1;
  }
  const View& v = *ud->ptr;
  const int in = net->spec.width(v.layer), out = net->spec.width(v.layer + 1);
  std::string s;
  switch (v.kind) {
    case View::kLayers: s = std::to_string(net->spec.layers()) + " layers of " + net->spec.describe(); break;
    case View::kLayer: s = layer_name(v) + " (" + std::to_string(in) + " -> " + std::to_string(out) + ")"; break;
    case View::kWeight: s = layer_name(v) + " weight (" + std::to_string(out) + "x" + std::to_string(in) + ")"; break;
    case View::kRow: s = layer_name(v) + " weight row " + std::to_string(v.row + 1) + " (" + std::to_string(in) + ")"; break;
    case View::kBias: s = layer_name(v) + " bias (" + std::to_string(out) + ")"; break;
  }
  lua_pushstring(L, s.c_str());
  return 1;
}

// ---- the network ----

// sn.mlp{ inputs (a count, or the input names), hidden = {...}, outputs, encoding, activation,
//         slope, omega, alpha, output_activation, init, seed, color, input_names }
int w_new(lua_State* L) {
  Options o(L, 1, "sn.mlp",
            {"inputs", "hidden", "outputs", "encoding", "activation", "slope", "omega", "alpha", "output_activation",
             "init", "seed", "color", "input_names"});
  nn::MlpSpec s;
  InputGroups groups;
  auto read_names = [&](const char* key) {
    const int at = o.push(key);
    if (!lua_istable(L, at)) throw Error(o.where(key) + ": table of strings expected, got " + type_name_at(L, at));
    const int n = check_list(L, at, o.where(key));
    for (int i = 1; i <= n; ++i) {
      lua_rawgeti(L, at, i);
      groups.names.push_back(check_string(L, -1, o.where(key).c_str()));
      groups.widths.push_back(nn::input_width(groups.names.back()));
      lua_pop(L, 1);
    }
    lua_pop(L, 1);
    for (std::size_t i = 0; i < groups.names.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (groups.names[i] == groups.names[j]) throw Error(o.where(key) + ": '" + groups.names[i] + "' is listed twice");
  };
  const int in_at = o.push("inputs");
  const bool named = lua_istable(L, in_at);
  lua_pop(L, 1);
  if (named) {  // inputs = { "normal", "view", "uv" }: the names, and their widths add up
    if (o.has("input_names")) throw Error("sn.mlp: give the input names once, as inputs = {...} or input_names = {...}");
    read_names("inputs");
    if (groups.names.empty()) throw Error(o.where("inputs") + ": at least one input name");
    s.inputs = groups.total();
  } else {
    s.inputs = o.int32("inputs");
    if (o.has("input_names")) read_names("input_names");
    // Checked here, not at the first render or training, which named the G-buffer's widths.
    if (!groups.names.empty() && groups.total() != s.inputs) {
      std::vector<std::string> widths;
      for (std::size_t i = 0; i < groups.names.size(); ++i)
        widths.push_back(groups.names[i] + " " + std::to_string(groups.widths[i]));
      throw Error("sn.mlp: input_names {" + join(groups.names) + "} describe " + std::to_string(groups.total()) +
                  " input columns (" + join(widths) + "; a name that is not a G-buffer attribute is a condition, 1), inputs = " +
                  std::to_string(s.inputs));
    }
  }
  s.outputs = o.int32("outputs", 3);
  for (double w : o.numbers("hidden")) {
    if (w != std::floor(w)) throw Error("sn.mlp option 'hidden': widths must be integers, got " + io::number_text(w));
    // The range before the int cast (1e10 said "got -2147483648"); MlpSpec::validate's words.
    if (!(w >= 1 && w <= nn::kMaxWidth))
      throw Error("sn.mlp: hidden layer " + std::to_string(s.hidden.size() + 1) + " width must be 1.." +
                  std::to_string(nn::kMaxWidth) + ", got " + io::number_text(w));
    s.hidden.push_back(int(w));
  }
  if (o.has("encoding")) {
    s.encodings = check_encodings(L, o.push("encoding"), groups, o.where("encoding"));
    lua_pop(L, 1);
  }
  s.activation = nn::parse_activation(o.string("activation", "tanh"), nn::Position::hidden);
  s.slope = o.number("slope", 0.01);
  s.omega = o.number("omega", 1.0);
  s.alpha = o.number("alpha", 1.0);
  s.output_activation = nn::parse_activation(o.string("output_activation", "linear"), nn::Position::output, "output_activation");
  // A parameter no activation of the network reads is a mistake (omega with tanh was ignored).
  for (auto p : {nn::ActivationParam::slope, nn::ActivationParam::omega, nn::ActivationParam::alpha}) {
    const char* name = nn::activation_param_name(p);
    if (o.has(name) && nn::activation_def(s.activation).param != p && nn::activation_def(s.output_activation).param != p) {
      std::vector<std::string> readers;
      for (const auto& a : nn::activation_names(nn::Position::hidden)) {
        nn::Activation act;
        if (nn::find_activation(a, &act) && nn::activation_def(act).param == p && activation_name(act) == a) readers.push_back(a);
      }
      throw Error(o.where(name) + ": neither activation of this network (" + nn::activation_name(s.activation) + ", " +
                  nn::activation_name(s.output_activation) + ") reads it; " + name + " is the parameter of " + join(readers));
    }
  }
  s.color = shading::parse_color_space(o.string("color", "rgb"));
  const nn::Init init = nn::parse_init(o.string("init", "xavier"));
  const uint64_t seed = o.seed("seed", 1);
  try {
    s.validate();
  } catch (const std::invalid_argument& e) {
    throw Error(std::string("sn.mlp: ") + e.what());
  }
  auto net = std::make_shared<Mlp>(s, init, seed);
  net->input_names = groups.names;
  push(L, std::move(net), kType);
  return 1;
}

int w_load(lua_State* L) {
  std::string path = check_string(L, 1, "sn.load path");
  push(L, std::make_shared<Mlp>(nn::load_checkpoint(path)), kType);
  return 1;
}

int w_save(lua_State* L) {
  nn::save_checkpoint(self(L), check_string(L, 2, "net:save path"));
  return 0;
}

int w_version(lua_State* L) {
  lua_pushnumber(L, double(self(L).version));
  return 1;
}

int w_trained_steps(lua_State* L) {
  lua_pushnumber(L, double(self(L).trained_steps));
  return 1;
}

int w_inputs(lua_State* L) {
  const Mlp& net = self(L);
  push_strings(L, net.input_names);
  return 1;
}

// net:conditions() -> { {name =, min =, max =, value =}, ... }: the inputs that are lighting-model
// parameters (a network trained on a dataset with `vary`), with their training ranges.
int w_conditions(lua_State* L) {
  const Mlp& net = self(L);
  lua_createtable(L, int(net.conditions.size()), 0);
  for (std::size_t i = 0; i < net.conditions.size(); ++i) {
    const auto& c = net.conditions[i];
    lua_createtable(L, 0, 4);
    lua_pushstring(L, c.name.c_str()), lua_setfield(L, -2, "name");
    lua_pushnumber(L, c.min), lua_setfield(L, -2, "min");
    lua_pushnumber(L, c.max), lua_setfield(L, -2, "max");
    lua_pushnumber(L, c.value), lua_setfield(L, -2, "value");
    lua_rawseti(L, -2, int(i + 1));
  }
  return 1;
}

// net:set_input(name, value): the value a condition input takes in renders from now on (live
// mode redraws with it). It must lie in the range the network was trained on.
int w_set_input(lua_State* L) {
  Mlp& net = self(L);
  std::string name = check_string(L, 2, "net:set_input name");
  double v = check_number(L, 3, "net:set_input value");
  for (auto& c : net.conditions) {
    if (c.name != name) continue;
    if (std::string why = nn::condition_value_problem(c, v); !why.empty()) throw Error("net:set_input: " + why);
    c.value = v;
    return 0;
  }
  std::string valid;
  for (const auto& c : net.conditions) valid += (valid.empty() ? "" : ", ") + c.name;
  throw Error("net:set_input: '" + name + "' is not a condition input of " + net.spec.describe() +
              " (its conditions: " + (valid.empty() ? "none; train it on a dataset with vary = {...}" : valid) + ")");
}

int w_restore_best(lua_State* L) {
  Mlp& net = self(L);
  lua_pushboolean(L, net.restore_best());
  return 1;
}

// net:best() -> { val_mse = , epoch = } of the last training run, or nil
int w_best(lua_State* L) {
  const Mlp& net = self(L);
  if (net.best_epoch == 0) return 0;
  lua_createtable(L, 0, 2);
  lua_pushnumber(L, net.best_val_mse);
  lua_setfield(L, -2, "val_mse");
  lua_pushinteger(L, net.best_epoch);
  lua_setfield(L, -2, "epoch");
  return 1;
}

int w_spec(lua_State* L) {
  const nn::MlpSpec& s = self(L).spec;
  lua_createtable(L, 0, 7);
  lua_pushinteger(L, s.inputs);
  lua_setfield(L, -2, "inputs");
  lua_createtable(L, int(s.hidden.size()), 0);
  for (std::size_t i = 0; i < s.hidden.size(); ++i) {
    lua_pushinteger(L, s.hidden[i]);
    lua_rawseti(L, -2, int(i + 1));
  }
  lua_setfield(L, -2, "hidden");
  lua_pushinteger(L, s.outputs);
  lua_setfield(L, -2, "outputs");
  lua_pushstring(L, nn::activation_name(s.activation));
  lua_setfield(L, -2, "activation");
  lua_pushnumber(L, s.slope);
  lua_setfield(L, -2, "slope");
  lua_pushnumber(L, s.omega);
  lua_setfield(L, -2, "omega");
  lua_pushnumber(L, s.alpha);
  lua_setfield(L, -2, "alpha");
  lua_pushstring(L, nn::activation_name(s.output_activation));
  lua_setfield(L, -2, "output_activation");
  lua_pushstring(L, shading::color_space_name(s.color));
  lua_setfield(L, -2, "color");
  push_encodings(L, s.encodings);
  lua_setfield(L, -2, "encoding");
  lua_pushinteger(L, s.width(0));
  lua_setfield(L, -2, "encoded_inputs");
  return 1;
}

// net:encode(x) -> what the first layer reads for raw inputs x (one sample: a table of inputs
// numbers; or a table of such tables), the encodings computed in double (the twins the cpu
// backend and the oracle use).
int w_encode(lua_State* L) {
  const Mlp& net = self(L);
  const nn::MlpSpec& s = net.spec;
  if (!lua_istable(L, 2)) throw Error("net:encode: a table of " + std::to_string(s.inputs) + " inputs, or a table of such tables, expected, got " + type_name_at(L, 2));
  lua_rawgeti(L, 2, 1);
  const bool nested = lua_istable(L, -1);
  lua_pop(L, 1);
  const int w = s.width(0);
  std::vector<double> enc(static_cast<std::size_t>(w));
  auto one = [&](int idx, const std::string& what) {
    const auto x = check_numbers(L, idx, what.c_str(), s.inputs);
    if (s.encodings.empty()) enc.assign(x.begin(), x.end());
    else nn::encode_row(s.encodings, s.inputs, x.data(), enc.data());
    lua_createtable(L, w, 0);
    for (int i = 0; i < w; ++i) {
      lua_pushnumber(L, enc[std::size_t(i)]);
      lua_rawseti(L, -2, i + 1);
    }
  };
  if (!nested) {
    one(2, "net:encode sample");
    return 1;
  }
  const int n = check_list(L, 2, "net:encode");
  lua_createtable(L, n, 0);
  for (int r = 1; r <= n; ++r) {
    lua_rawgeti(L, 2, r);
    one(lua_gettop(L), "net:encode sample " + std::to_string(r));
    lua_remove(L, -2);
    lua_rawseti(L, -2, r);
  }
  return 1;
}

// net:params() -> every parameter in the shared flat layout (per layer: weights row-major, biases)
int w_params(lua_State* L) {
  const Mlp& net = self(L);
  push_vector(L, net.params.data(), int(net.params.size()));
  return 1;
}

int w_set_params(lua_State* L) {
  Mlp& net = self(L);
  std::vector<float> p(net.params.size());
  read_vector(L, 2, int(p.size()), p.data(), "net:set_params");
  net.params = std::move(p);
  net.touch();
  return 0;
}

// net:clone() -> an independent copy (weights, names, counters; version starts over)
int w_clone(lua_State* L) {
  auto copy = std::make_shared<Mlp>(self(L));
  copy->version = 1;
  push(L, std::move(copy), kType);
  return 1;
}

int w_index(lua_State* L) {
  auto& box = check_box<Mlp>(L, 1, kType);
  if (lua_type(L, 2) == LUA_TSTRING && std::string(lua_tostring(L, 2)) == "layers") {
    push_view(L, {View::kLayers, box, 0, 0}, 1, false);
    return 1;
  }
  lua_pushvalue(L, 2);
  lua_rawget(L, lua_upvalueindex(1));
  if (!lua_isnil(L, -1)) return 1;
  // Not a method: registry["shadenet.unknown_field"] (shadenet.lua) words the error.
  lua_getfield(L, LUA_REGISTRYINDEX, "shadenet.unknown_field");
  if (lua_isnil(L, -1)) return 1;  // the Lua side is not loaded (the core alone): nil, as a table would
  lua_pushstring(L, kType);
  lua_pushvalue(L, 2);
  lua_newtable(L);  // the names: the methods and `layers`
  lua_pushnil(L);
  while (lua_next(L, lua_upvalueindex(1))) {
    lua_pushvalue(L, -2);
    lua_insert(L, -2);
    lua_settable(L, -4);
  }
  lua_pushboolean(L, 1);
  lua_setfield(L, -2, "layers");
  pcall_or_throw(L, 3, 1, "shadenet.unknown_field");
  throw Error(lua_tostring(L, -1));
}

int w_newindex(lua_State* L) {
  check_box<Mlp>(L, 1, kType);
  throw Error("Mlp fields cannot be set; edit weights through net.layers[i].weight / .bias");
}

int w_tostring(lua_State* L) {
  auto* ud = static_cast<Box<Mlp>*>(test_type(L, 1, kType));
  if (!ud || !ud->ptr) lua_pushstring(L, "Mlp (released)");
  else lua_pushstring(L, ud->ptr->spec.describe().c_str());
  return 1;
}

int w_eq(lua_State* L) {
  auto* a = static_cast<Box<Mlp>*>(test_type(L, 1, kType));
  auto* b = static_cast<Box<Mlp>*>(test_type(L, 2, kType));
  lua_pushboolean(L, a && b && a->ptr && a->ptr == b->ptr);
  return 1;
}

// Replaces the metatable's __index table with a function that serves `field` first and the
// methods (kept in "__methods", so others can add to them) after.
void index_through(lua_State* L, const char* type, lua_CFunction index) {
  luaL_getmetatable(L, type);
  lua_getfield(L, -1, "__index");
  lua_pushvalue(L, -1);
  lua_setfield(L, -3, "__methods");
  lua_pushcclosure(L, index, 1);
  lua_setfield(L, -2, "__index");
  lua_pop(L, 1);
}

}  // namespace

void open_mlp(lua_State* L) {
  static const luaL_Reg methods[] = {
      SN_FN("save", w_save),       SN_FN("version", w_version),   SN_FN("trained_steps", w_trained_steps),
      SN_FN("inputs", w_inputs),   SN_FN("conditions", w_conditions), SN_FN("set_input", w_set_input),   SN_FN("restore_best", w_restore_best), SN_FN("best", w_best),
      SN_FN("spec", w_spec),       SN_FN("params", w_params),     SN_FN("set_params", w_set_params),
      SN_FN("clone", w_clone),     SN_FN("encode", w_encode),     {nullptr, nullptr}};
  static const luaL_Reg meta[] = {SN_FN("__newindex", w_newindex), SN_FN("__eq", w_eq), {nullptr, nullptr}};
  define_box_type<Mlp>(L, kType, methods, wrap<w_tostring>, meta);
  index_through(L, kType, wrap<w_index>);

  static const luaL_Reg view_methods[] = {{nullptr, nullptr}};
  static const luaL_Reg view_meta[] = {SN_FN("__newindex", w_view_newindex), SN_FN("__len", w_view_len),
                                       {nullptr, nullptr}};
  define_box_type<View>(L, kView, view_methods, wrap<w_view_tostring>, view_meta);
  // view:table() is looked up by name in __index; its upvalue is the function itself.
  luaL_getmetatable(L, kView);
  lua_pushcfunction(L, wrap<w_view_table>);
  lua_pushcclosure(L, wrap<w_view_index>, 1);
  lua_setfield(L, -2, "__index");
  lua_pop(L, 1);

  lua_pushcfunction(L, wrap<w_new>);
  lua_setfield(L, -2, "mlp");
  lua_pushcfunction(L, wrap<w_load>);
  lua_setfield(L, -2, "load");
}

std::vector<std::shared_ptr<nn::Mlp>> check_mlp_list(lua_State* L, int idx, const std::string& where) {
  std::vector<std::shared_ptr<nn::Mlp>> nets;
  if (test_type(L, idx, kType)) {
    nets.push_back(check_shared<nn::Mlp>(L, idx, kType));
  } else if (lua_istable(L, idx)) {
    const int n = check_list(L, idx, where);
    for (int i = 1; i <= n; ++i) {
      lua_rawgeti(L, idx, i);
      if (!test_type(L, -1, kType))
        throw Error(where + ": element " + std::to_string(i) + " is " + type_name_at(L, -1) + ", not an Mlp");
      nets.push_back(check_shared<nn::Mlp>(L, -1, kType));
      lua_pop(L, 1);
    }
  } else {
    throw Error(where + ": an Mlp or a table of them expected, got " + type_name_at(L, idx));
  }
  return nets;
}

}  // namespace sn::lua

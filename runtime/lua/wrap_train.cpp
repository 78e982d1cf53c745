// sn.train{...}: one training job over many networks (nn/train.h). Everything is checked before
// any work; the result is one table per network, in the order of `nets`.
#include <atomic>
#include <cmath>
#include <cstdio>
#include <set>
#include <unistd.h>

#include "lua/binding.h"
#include "lua/mlp_binding.h"
#include "lua/interrupt.h"
#include "lua/module.h"
#include "data/dataset.h"
#include "io/text.h"
#include "nn/train.h"

namespace sn::lua {

namespace {

void push_numbers(lua_State* L, const std::vector<double>& v) {
  lua_createtable(L, int(v.size()), 0);
  for (std::size_t i = 0; i < v.size(); ++i) {
    lua_pushnumber(L, v[i]);
    lua_rawseti(L, -2, int(i + 1));
  }
}

void set_number(lua_State* L, const char* key, double v) {
  lua_pushnumber(L, v);
  lua_setfield(L, -2, key);
}

void set_string(lua_State* L, const char* key, const std::string& v) {
  lua_pushstring(L, v.c_str());
  lua_setfield(L, -2, key);
}

void push_result(lua_State* L, const nn::NetResult& r, const nn::JobResult& job) {
  lua_createtable(L, 0, 12);
  push_numbers(L, r.train_mse);
  lua_setfield(L, -2, "train_mse");
  push_numbers(L, r.val_mse);
  lua_setfield(L, -2, "val_mse");
  set_string(L, "loss", r.loss);
  push_numbers(L, r.train_loss);
  lua_setfield(L, -2, "train_loss");
  push_numbers(L, r.val_loss);
  lua_setfield(L, -2, "val_loss");
  if (r.best_epoch > 0) {
    set_number(L, "best_val_mse", r.best_val_mse);
    set_number(L, "best_epoch", r.best_epoch);
    set_number(L, "best_val_loss", r.val_loss[std::size_t(r.best_epoch - 1)]);
  }
  set_number(L, "wall_time", r.wall_time);
  set_number(L, "sample_steps_per_s", r.sample_steps_per_s);
  set_number(L, "steps", double(r.steps));
  set_number(L, "initial_val_mse", r.initial_val_mse);
  set_number(L, "epochs", r.epochs_done());
  if (r.diverged) {
    lua_createtable(L, 0, 3);
    set_number(L, "epoch", r.diverged->epoch);
    set_number(L, "step", double(r.diverged->step));
    set_string(L, "reason", nn::divergence_kind_name(r.diverged->kind));
    lua_setfield(L, -2, "diverged");
  }
  if (r.interrupted) {
    lua_createtable(L, 0, 2);
    set_number(L, "epoch", r.interrupted->epoch);
    set_number(L, "step", double(r.interrupted->step));
    lua_setfield(L, -2, "interrupted");
  }
  push_numbers(L, r.dead_units);
  lua_setfield(L, -2, "dead_units");
  if (r.stuck_outputs >= 0) set_number(L, "stuck_outputs", r.stuck_outputs);
  set_string(L, "backend", job.backend);
  set_string(L, "device", job.device);
}

// sn.train{ nets = {net, ...} | net, data = dataset, epochs = 20, batch = 8,
//           adam = { lr = 2.5e-4, beta1 = 0.8, beta2 = 0.9, eps = 1e-7 }, seed = 1 | {seed per net},
//           backend = "auto" | "cpu" | "gl", keep = "last" | "best", progress = function(e),
//           tick = function(t), tick_seconds = 0.1,
//           loss = "l2" | "l1" | "relative_l2" | "huber" | { "huber", delta = 1 },
//           divergence_factor = 100 }
// The first Ctrl-C, or progress returning "stop", ends the job at the next step boundary; the
// results say `interrupted = { epoch, step }` (lua/interrupt.h, nn/train.h).
nn::Loss read_loss(lua_State* L, int idx) {
  const char* where = "sn.train option 'loss'";
  if (lua_isnil(L, idx)) return nn::Loss{};
  if (lua_type(L, idx) == LUA_TSTRING) return nn::parse_loss(lua_tostring(L, idx));
  if (!lua_istable(L, idx)) throw Error(std::string(where) + ": a name or { name, delta = ... } expected, got " + type_name_at(L, idx));
  double delta = 1.0;
  bool has_delta = false;
  std::string name;
  lua_pushnil(L);
  while (lua_next(L, idx) != 0) {
    const bool first = lua_type(L, -2) == LUA_TNUMBER && lua_tonumber(L, -2) == 1;
    const bool is_delta = lua_type(L, -2) == LUA_TSTRING && std::string(lua_tostring(L, -2)) == "delta";
    if (first && lua_type(L, -1) == LUA_TSTRING) name = lua_tostring(L, -1);
    else if (is_delta && lua_type(L, -1) == LUA_TNUMBER) delta = lua_tonumber(L, -1), has_delta = true;
    else {
      lua_pop(L, 2);
      throw Error(std::string(where) + ": valid entries are [1] = the loss's name and delta = a number (huber)");
    }
    lua_pop(L, 1);
  }
  if (name.empty()) throw Error(std::string(where) + ": the table's first entry must be the loss's name");
  nn::Loss loss = nn::parse_loss(name, delta);
  // Given at all, not only where it differs from the default: {"l2", delta = 1} was taken.
  if (loss.kind != nn::LossKind::huber && has_delta) throw Error(std::string(where) + ": only huber takes a delta");
  return loss;
}

int w_train(lua_State* L) {
  Options o(L, 1, "sn.train", {"nets", "data", "epochs", "batch", "adam", "seed", "backend", "keep", "progress", "tick",
                                     "tick_seconds", "loss", "divergence_factor"});
  nn::TrainJob job;
  // Keep every network (and the dataset) referenced from this stack frame while training runs.
  const std::vector<std::shared_ptr<nn::Mlp>> hold = check_mlp_list(L, o.push("nets"), "sn.train option 'nets'");
  lua_pop(L, 1);
  for (auto& p : hold) job.nets.push_back(p.get());

  int data = o.push("data");
  if (lua_isnil(L, data)) throw Error("sn.train option 'data' is required (a Dataset)");
  auto dataset = check_shared<data::Dataset>(L, data, "Dataset");
  lua_pop(L, 1);
  job.data = dataset.get();

  nn::TrainConfig& c = job.config;
  c.epochs = o.int32("epochs", c.epochs);
  c.batch = o.int32("batch", c.batch);
  // The shuffle seed: one for every net, or a table with each net's own.
  if (lua_istable(L, o.push("seed"))) {
    const std::vector<double> seeds = o.numbers("seed");
    if (seeds.size() != job.nets.size())
      throw Error("sn.train option 'seed': one seed per net, got " + std::to_string(seeds.size()) + " for " +
                  std::to_string(job.nets.size()) + " nets");
    for (std::size_t i = 0; i < seeds.size(); ++i)
      c.seeds.push_back(uint32_t(check_seed(seeds[i], "sn.train option 'seed' entry " + std::to_string(i + 1), kSeed32Max)));
  } else {
    c.seed = uint32_t(o.seed("seed", c.seed, kSeed32Max));
  }
  lua_pop(L, 1);
  int adam = o.push("adam");
  if (!lua_isnil(L, adam)) {
    Options a(L, adam, "sn.train option 'adam'", {"lr", "beta1", "beta2", "eps"});
    c.lr = a.number("lr", c.lr);
    c.beta1 = a.number("beta1", c.beta1);
    c.beta2 = a.number("beta2", c.beta2);
    c.eps = a.number("eps", c.eps);
  }
  lua_pop(L, 1);
  c.divergence.factor = o.number("divergence_factor", c.divergence.factor);

  try {
    c.loss = read_loss(L, o.push("loss"));
  } catch (const std::invalid_argument& e) {
    throw Error(std::string("sn.train: ") + e.what());
  }
  lua_pop(L, 1);

  const std::string backend = o.string("backend", "auto");
  if (backend != "auto" && !nn::has_backend(backend)) {
    std::string avail = "auto";
    for (auto& n : nn::backend_names()) avail += ", " + n;
    throw Error("sn.train: unknown backend '" + backend + "' (available: " + avail + ")");
  }
  job.backend = backend;
  job.keep = o.choice("keep", {"last", "best"}, 0) == 0 ? nn::Keep::last : nn::Keep::best;

  // One stop flag for Ctrl-C and progress's "stop" (the job reads it at every step boundary).
  std::atomic<bool> stop{false};
  job.stop = &stop;
  // The progress and tick functions run on this thread (between epochs; about every
  // tick_seconds during them). Returning "stop" sets the stop flag; a Lua error inside stops the
  // job too, which keeps what was trained and then raises it (pcall, then a C++ exception: a
  // longjmp must not cross the trainer's frames).
  auto hook = [L, &stop](int fn, const char* what, auto push_event) {
    lua_pushvalue(L, fn);
    push_event();
    pcall_or_throw(L, 1, 1, std::string("sn.train: the ") + what + " function");
    const bool is_stop = lua_type(L, -1) == LUA_TSTRING && std::string(lua_tostring(L, -1)) == "stop";
    if (!is_stop && !lua_isnil(L, -1)) {
      std::string got = type_name_at(L, -1);
      if (lua_type(L, -1) == LUA_TSTRING) got.append(" '").append(lua_tostring(L, -1)).append("'");
      lua_pop(L, 1);
      throw Error(std::string("sn.train: the ") + what + " function returned " + got +
                  "; return \"stop\" to end training, or nothing to go on");
    }
    lua_pop(L, 1);
    if (is_stop) stop.store(true);
  };
  auto function_option = [&](const char* name) {
    int idx = o.push(name);  // a function stays on the stack for the job's duration
    if (lua_isnil(L, idx)) {
      lua_pop(L, 1);
      return 0;
    }
    if (!lua_isfunction(L, idx))
      throw Error(std::string("sn.train option '") + name + "': function expected, got " + type_name_at(L, idx));
    return idx;
  };
  if (int progress = function_option("progress")) {
    const bool l2 = c.loss.kind == nn::LossKind::l2;
    job.progress = [L, progress, l2, hook, &hold](const nn::ProgressEvent& e) {
      // The net as it is after this epoch, for a checkpoint or render per epoch (the job's end
      // replaces it with what was trained, an edit made here included).
      if (e.params) {
        nn::Mlp& net = *hold[std::size_t(e.net)];
        net.params = *e.params;
        net.touch();
      }
      hook(progress, "progress", [&] {
        lua_createtable(L, 0, 5);
        set_number(L, "net", e.net + 1);
        set_number(L, "epoch", e.epoch);
        set_number(L, "train_loss", e.train_loss);
        if (l2) set_number(L, "train_mse", e.train_loss);
        set_number(L, "val_loss", e.val_loss);
        set_number(L, "val_mse", e.val_mse);
      });
    };
  }
  if (int tick = function_option("tick")) {
    c.tick_seconds = o.number("tick_seconds", c.tick_seconds);
    c.tick = [L, tick, hook](const nn::TickEvent& e) {
      hook(tick, "tick", [&] {
        lua_createtable(L, 0, 5);
        set_number(L, "epoch", e.epoch);
        set_number(L, "epochs", e.epochs);
        set_number(L, "step", double(e.step));
        set_number(L, "steps", double(e.steps));
        // Of the whole job: epochs before this one count in full.
        set_number(L, "fraction", (double(e.epoch - 1) * double(e.steps) + double(e.step)) /
                                      (double(e.epochs) * double(std::max(1LL, e.steps))));
      });
    };
  } else if (o.has("tick_seconds")) {
    throw Error("sn.train option 'tick_seconds' needs a tick function (option 'tick')");
  }

  try {
    nn::validate(job);
  } catch (const std::invalid_argument& e) {
    throw Error(std::string("sn.train: ") + e.what());
  }
  // A progress or tick function may start a job of its own, but not on a net of this one: each
  // job commits its nets when it ends, and the later commit would silently replace the other's.
  static std::set<const nn::Mlp*> training;
  for (std::size_t i = 0; i < hold.size(); ++i)
    if (training.count(hold[i].get()))
      throw Error("sn.train: net " + std::to_string(i + 1) +
                  " is being trained by a job that has not ended (its progress or tick function called this one)");
  struct Busy {
    const std::vector<std::shared_ptr<nn::Mlp>>& nets;
    explicit Busy(const std::vector<std::shared_ptr<nn::Mlp>>& n) : nets(n) {
      for (auto& p : nets) training.insert(p.get());
    }
    ~Busy() {
      for (auto& p : nets) training.erase(p.get());
    }
  } busy(hold);
  // The backend auto picks, said once per process (a sweep calls sn.train many times) when it is
  // picked, not after the training; on a terminal it clears a progress line drawn on it first.
  static bool said = false;
  if (backend == "auto" && !said) {
    std::string reason;
    const std::string picked = nn::resolve_backend(backend, &reason, job.nets);
    const bool same_terminal = isatty(STDOUT_FILENO) == 1 && isatty(STDERR_FILENO) == 1;
    std::fflush(stdout);
    std::fprintf(stderr, "%ssn.train: backend auto -> %s (%s)\n", same_terminal ? "\r\033[K" : "", picked.c_str(),
                 reason.c_str());
    said = true;
  }
  nn::JobResult r;
  {
    TrainInterrupt ctrl_c(&stop);
    r = nn::train(job);
  }
  lua_settop(L, 1);  // the progress and tick functions

  lua_createtable(L, int(r.nets.size()), 0);
  for (std::size_t i = 0; i < r.nets.size(); ++i) {
    push_result(L, r.nets[i], r);
    lua_rawseti(L, -2, int(i + 1));
  }
  return 1;
}

// sn.backends() -> names of the training backends in this build ("cpu", "gl", ...)
int w_backends(lua_State* L) {
  auto names = nn::backend_names();
  push_strings(L, names);
  return 1;
}

}  // namespace

void open_train(lua_State* L) {
  lua_pushcfunction(L, wrap<w_train>);
  lua_setfield(L, -2, "train");
  lua_pushcfunction(L, wrap<w_backends>);
  lua_setfield(L, -2, "backends");
}

}  // namespace sn::lua

// The training contract every backend implements (cpu: nn/cpu_trainer.h, gl: nn/gl_trainer.h)
// and the job around it (nn/train.h: validation, backend choice, diagnostics, commit to nets).
//
// What one run computes, identical on every backend:
//  - loss: the mean over the minibatch's samples and the network's outputs of a per-component
//    loss of net(x) - y (nn/loss.h; l2, the MSE, by default), in the dataset's (= the network's)
//    colour space.
//  - epoch e (0-based) visits the training rows in the order nn::shuffle_index(seed, e, k, n)
//    (seed: the net's, TrainConfig::seed_of)
//    for k = 0..n-1 (nn/shuffle.h); step s takes rows k = s*batch .. s*batch+batch-1;
//    steps per epoch = n / batch (a partial last minibatch is dropped; it changes every epoch).
//  - Adam (Kingma & Ba, Algorithm 1) with t = 1, 2, ... counted from the start of the run and
//    fresh moments m = v = 0 per run:
//      m = b1*m + (1-b1)*g;  v = b2*v + (1-b2)*g*g;
//      w -= lr * (m / (1 - b1^t)) / (sqrt(v / (1 - b2^t)) + eps)
//  - train_loss[e] = mean of the minibatch losses of epoch e (each taken in that step's forward
//    pass, before its update); val_loss[e] = the loss over all validation rows after epoch e,
//    val_mse[e] their MSE (always, so that runs with different losses compare). For l2,
//    train_mse = train_loss; with another loss train_mse stays empty. The best epoch is the
//    one of the lowest val_mse.
//  - divergence, one rule for every backend (docs/reliability.md):
//      a step whose loss (per sample, in float; the batch's sum in double) or new parameters are
//      not finite is not applied: the net stops with the parameters from before that step,
//      `diverged` = {epoch, step (the step not applied), nonfinite}; a step in which a sample's
//      squared error is above DivergenceRule::sample_limit is refused the same way, `exploded`
//      (checked after the loss, before the update);
//      after each epoch, NetResult::end_epoch applies DivergenceRule to the validation MSE: a
//      net whose MSE is not finite, or is above `factor` times its best so far (the untrained
//      net's included) and above the constant predictor's, stops with the parameters it has,
//      `diverged` = {epoch, steps per epoch, exploded}.
//  - stopping: when cfg.stop is set and becomes true (Ctrl-C, a progress function's "stop"),
//    every net still training stops at its next step boundary, keeps what it has and records
//    `interrupted` = {finished epochs + 1, steps applied in that epoch}; the job (nn/train.h)
//    writes a stop at an epoch's start as the end of the epoch before.
#pragma once
#include <algorithm>
#include <atomic>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "data/dataset.h"
#include "nn/loss.h"
#include "nn/mlp.h"

namespace sn::nn {

// The loss-explosion rule: after epoch e a net has exploded when its validation MSE is not
// finite, or when it is above both `factor` x the lowest validation MSE before e (the untrained
// net's, NetResult::initial_val_mse, included) and `constant_mse`, the MSE of predicting the
// training targets' mean (data::Dataset; the job fills it in, nn/train.h). Either bound alone
// misfires: a near-perfect net's validation MSE may jump 100x and still beat the mean; a net
// that never beat the mean is not exploding while it improves. A negative constant_mse (backends
// called directly, without the job) leaves only the non-finite check.
//
// Within an epoch the rule has a bound on each training sample: a step in which a sample's
// squared error (summed over its outputs) is above kSampleFactor x outputs x the larger of
// constant_mse and the untrained net's validation MSE is refused like a non-finite one, and the
// net stops (`exploded`). Far beyond what training reaches (10^6 x the reference error), it
// catches a blow-up before float overflow does: overflow turns a step into NaN at whichever step
// the last bits of each backend's arithmetic decide, a squared error of 10^31 is seen alike.
// factor = infinity turns both bounds off (only non-finite steps and MSEs stop a net).
struct DivergenceRule {
  static constexpr double kSampleFactor = 1e12;
  double factor = 100;
  double constant_mse = -1;
  // Defined in nn/train.cpp, the job's rule.
  bool exploded(double val_mse, double best_before) const;
  float sample_limit(double initial_val_mse, int outputs) const;  // +inf: no bound
};

// Where a run is, for a tick (TrainConfig::tick): epoch `epoch` (1-based) of `epochs` is under
// way and its nets have applied `step` of its `steps` steps (the mean over the nets that began
// the epoch; one that stopped counts as done).
struct TickEvent {
  int epoch = 0, epochs = 0;
  long long step = 0, steps = 0;
};
using Tick = std::function<void(const TickEvent&)>;

struct TrainConfig {
  int epochs = 20;
  int batch = 8;
  double lr = 2.5e-4, beta1 = 0.8, beta2 = 0.9, eps = 1e-7;  // the thesis' Adam settings
  uint32_t seed = 1;  // shuffle seed of the job's nets
  // Per net, its own shuffle seed instead (empty: `seed` for all). A net's result depends on its
  // seed only, never on the job it shares: a sweep's seeds can train in one job.
  std::vector<uint32_t> seeds;
  uint32_t seed_of(std::size_t net) const { return seeds.empty() ? seed : seeds[net]; }
  // The different seeds of nets 0 .. nets-1, in the order of their first net.
  std::vector<uint32_t> distinct_seeds(std::size_t nets) const {
    std::vector<uint32_t> out;
    for (std::size_t i = 0; i < nets; ++i)
      if (std::find(out.begin(), out.end(), seed_of(i)) == out.end()) out.push_back(seed_of(i));
    return out;
  }
  Loss loss;
  DivergenceRule divergence;
  // The job's stop flag (nullptr: never stops early). Backends read it at every step boundary.
  const std::atomic<bool>* stop = nullptr;
  bool stop_requested() const { return stop && stop->load(std::memory_order_relaxed); }
  // Called on the thread that called train() about every tick_seconds while epochs run (not
  // only between them): a window keeps drawing during an epoch of any length. It may set the
  // stop flag; it never changes what is computed. Empty: the backends work as without it.
  Tick tick;
  double tick_seconds = 0.1;
  // Per net, the untrained weights' validation MSE as the job measured it (on the cpu, so that
  // every backend starts the divergence rule from the same numbers); NaN or missing: the
  // backend measures it.
  std::vector<double> initial_val_mse;
  double initial_val_mse_of(std::size_t net) const {
    return net < initial_val_mse.size() ? initial_val_mse[net] : std::numeric_limits<double>::quiet_NaN();
  }
};

enum class DivergenceKind { nonfinite, exploded };
const char* divergence_kind_name(DivergenceKind k);  // "nonfinite", "exploded"

struct Divergence {
  int epoch = 0;     // 1-based
  long long step = 0;  // 1-based within that epoch: nonfinite, the step not applied; exploded, the epoch's last
  DivergenceKind kind = DivergenceKind::nonfinite;
};

// Where a stopped run ended: after step `step` (1-based; 0 = before the first) of epoch `epoch`.
struct StopPoint {
  int epoch = 0;
  long long step = 0;
};

// One network's run. A backend fills the curves through end_epoch() and `diverged`; the job
// (nn/train.h) fills the rest.
struct NetResult {
  std::vector<double> train_loss, val_loss, val_mse;  // per finished epoch
  std::vector<double> train_mse;  // = train_loss for l2, else empty
  std::string loss = "l2";        // Loss::describe() of the run's loss
  double best_val_mse = 0;
  int best_epoch = 0;  // 1-based, 0 = no epoch finished
  std::vector<float> best_params;  // parameters after best_epoch
  std::vector<float> final_params;  // parameters at the end (last finite ones when diverged)
  long long steps = 0;  // Adam steps applied
  std::optional<Divergence> diverged;
  std::optional<StopPoint> interrupted;  // set when the job's stop flag ended this net's run early
  int epochs_done() const { return int(val_mse.size()); }
  double initial_val_mse = 0;  // validation MSE of the parameters the run started from
  double wall_time = 0;  // seconds for the whole job (all nets train together)
  double sample_steps_per_s = 0;  // this net's steps * batch / wall_time
  std::vector<double> dead_units;  // per hidden layer, see nn/diagnostics.h
  int stuck_outputs = -1;          // output channels constant over the validation rows (-1: not measured)

  // Appends an epoch; keeps a copy of `params` when val_mse is a new minimum (first wins ties).
  // Returns false, with `diverged` set, when cfg.divergence says the net exploded: the backend
  // stops training it.
  bool end_epoch(const TrainConfig& cfg, long long steps_per_epoch, double train_loss, double val_mse,
                 double val_loss, const float* params, std::size_t count);
};

struct ProgressEvent {
  int net = 0;    // 0-based index into the job's nets
  int epoch = 0;  // 1-based, just finished
  double train_loss = 0, val_mse = 0, val_loss = 0;
  const std::vector<float>* params = nullptr;  // the net's parameters after the epoch (Mlp::params' layout)
};
// Called on the thread that called train(), after each finished epoch of each net (order across
// nets unspecified). To end the run early it sets the job's stop flag (TrainJob::stop). An
// exception thrown by it ends the run the same way (the job commits what was trained, then
// rethrows it, nn/train.h).
using Progress = std::function<void(const ProgressEvent&)>;

class Backend {
 public:
  virtual ~Backend() = default;
  virtual std::string name() const = 0;  // "cpu", "gl"
  virtual std::string device() const = 0;  // e.g. "AMD EPYC, 2 threads" or the GL renderer
  // Trains copies of nets[i]->params (the nets themselves are left untouched: the job commits
  // final_params). Inputs are already validated by the job (nn/train.h): every spec is valid,
  // shares data.inputs/outputs and colour space, batch <= data.train_count(), data is finite.
  virtual std::vector<NetResult> train(const std::vector<const Mlp*>& nets, const data::Dataset& data,
                                       const TrainConfig& cfg, const Progress& progress) = 0;
  // How many distinct shuffle seeds (TrainConfig::seeds) train() takes in one call, for a
  // dataset of `train_rows`; the job (nn/train.h) splits a job with more into calls of at most
  // that many, each seed's nets in one call.
  virtual std::size_t seeds_per_call(std::size_t /*train_rows*/) const { return 1; }
};

std::unique_ptr<Backend> make_cpu_backend();
// Defined in nn/gl_trainer.cpp. A static library drops object files nothing references, so
// nothing here calls it: the gl side registers it with register_backend("gl", make_gl_backend)
// from code that is linked (its Lua open_* function), and its unit tests call it directly.
std::unique_ptr<Backend> make_gl_backend();

using BackendFactory = std::unique_ptr<Backend> (*)();
void register_backend(const std::string& name, BackendFactory factory);  // replaces a same-named one
bool has_backend(const std::string& name);
std::vector<std::string> backend_names();  // registered, sorted; "cpu" is always there
// Throws "unknown backend 'x' (available: cpu, gl)".
std::unique_ptr<Backend> make_backend(const std::string& name);

}  // namespace sn::nn

// The training contract every backend implements (cpu: nn/cpu_trainer.h, gl: nn/gl_trainer.h)
// and the job around it (nn/train.h: validation, backend choice, diagnostics, commit to nets).
//
// What one run computes, identical on every backend:
//  - loss: the mean over the minibatch's samples and the network's outputs of a per-component
//    loss of net(x) - y (nn/loss.h; l2, the MSE, by default), in the dataset's (= the network's)
//    colour space.
//  - epoch e (0-based) visits the training rows in the order nn::shuffle_index(seed, e, k, n)
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
//  - divergence: a step whose loss or new parameters are not finite is not applied; the net
//    stops with its parameters from before that step and `diverged` = {epoch, step} (1-based).
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "data/dataset.h"
#include "nn/loss.h"
#include "nn/mlp.h"

namespace sn::nn {

struct TrainConfig {
  int epochs = 20;
  int batch = 8;
  double lr = 2.5e-4, beta1 = 0.8, beta2 = 0.9, eps = 1e-7;  // the thesis' Adam settings
  uint32_t seed = 1;  // shuffle seed, shared by all nets of the job
  Loss loss;
};

struct Divergence {
  int epoch = 0;     // 1-based
  long long step = 0;  // 1-based within that epoch
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
  double wall_time = 0;  // seconds for the whole job (all nets train together)
  double sample_steps_per_s = 0;  // this net's steps * batch / wall_time
  std::vector<double> dead_units;  // per hidden layer, see nn/diagnostics.h

  // Appends an epoch; keeps a copy of `params` when val_mse is a new minimum (first wins ties).
  void end_epoch(const Loss& loss, double train_loss, double val_mse, double val_loss, const float* params,
                 std::size_t count);
};

struct ProgressEvent {
  int net = 0;    // 0-based index into the job's nets
  int epoch = 0;  // 1-based, just finished
  double train_loss = 0, val_mse = 0, val_loss = 0;
};
// Called on the thread that called train(), after each finished epoch of each net (order across
// nets unspecified). An exception thrown by it aborts the run; the nets keep their parameters.
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

// A training job: checks everything a person can get wrong before any work, picks the backend,
// runs it, then commits the results to the networks (final or best weights, step counters,
// version bump, input names) and adds the dead-unit diagnostics.
#pragma once
#include <atomic>
#include <string>
#include <vector>

#include "nn/trainer.h"

namespace sn::nn {

// Which weights a network keeps after the job: the final ones (default, what the curves end
// on) or those of the epoch with the lowest validation MSE. Both stay reachable: the other is
// Mlp::best_params (restore_best()). After a stop part-way through an epoch, last = the weights
// after the last step applied, best = those of the finished epoch with the lowest validation MSE
// (a partial epoch is never validated), or last when no epoch finished.
enum class Keep { last, best };

struct TrainJob {
  std::vector<Mlp*> nets;
  const data::Dataset* data = nullptr;
  TrainConfig config;
  std::string backend = "auto";  // "auto" | a registered backend ("cpu", "gl")
  Keep keep = Keep::last;
  Progress progress;
  // The stop flag the backends read at every step boundary (nullptr: the job's own, which only
  // a failing progress function sets). Whoever holds it may set it from any thread or a signal
  // handler (sn.train: Ctrl-C, a progress function returning "stop"); each net then keeps what
  // it trained and is flagged `interrupted`.
  std::atomic<bool>* stop = nullptr;
};

struct JobResult {
  std::string backend, device;
  std::string reason;  // why this backend (for "auto")
  double wall_time = 0;
  std::vector<NetResult> nets;
};

// The MSE over the validation rows of predicting each output's mean over the training rows (the
// divergence rule's bound, nn/trainer.h); -1 without rows.
double constant_predictor_mse(const data::Dataset& data);
// Throws std::invalid_argument naming the net (1-based), field and valid range.
void validate(const TrainJob& job);
// Every input and target of the dataset is finite and the row counts add up; throws naming the
// first bad row and column (1-based).
void check_dataset(const data::Dataset& data);
// "auto" -> "gl" on a hardware GPU when the gl backend is built in, or when a net has an
// activation without cpu code (a definition whose GLSL does not translate); else "cpu". "cpu"
// with such a net throws naming the net, the reason and backend = "gl".
std::string resolve_backend(const std::string& requested, std::string* reason, const std::vector<Mlp*>& nets = {});
JobResult train(const TrainJob& job);

}  // namespace sn::nn

#include "nn/trainer.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>

namespace sn::nn {

const char* divergence_kind_name(DivergenceKind k) { return k == DivergenceKind::exploded ? "exploded" : "nonfinite"; }

bool NetResult::end_epoch(const TrainConfig& cfg, long long steps_per_epoch, double train, double val, double vloss,
                          const float* params, std::size_t count) {
  const Loss& l = cfg.loss;
  // The lowest validation MSE before this epoch, the untrained net's included (NaN ones skipped).
  double best_before = initial_val_mse;
  if (best_epoch > 0 && !(best_val_mse >= best_before)) best_before = best_val_mse;
  loss = l.describe();
  train_loss.push_back(train);
  if (l.kind == LossKind::l2) train_mse.push_back(train);
  val_mse.push_back(val);
  val_loss.push_back(vloss);
  // A NaN validation MSE never counts as the best (nor blocks a later finite one).
  if (best_epoch == 0 || val < best_val_mse || (std::isnan(best_val_mse) && !std::isnan(val))) {
    best_val_mse = val;
    best_epoch = int(val_mse.size());
    best_params.assign(params, params + count);
  }
  if (!cfg.divergence.exploded(val, best_before)) return true;
  diverged = Divergence{int(val_mse.size()), steps_per_epoch, DivergenceKind::exploded};
  return false;
}

namespace {
struct Registry {
  std::mutex mutex;
  std::map<std::string, BackendFactory> factories{{"cpu", &make_cpu_backend}};
};
Registry& registry() {
  static Registry r;
  return r;
}
}  // namespace

void register_backend(const std::string& name, BackendFactory factory) {
  std::lock_guard lock(registry().mutex);
  registry().factories[name] = factory;
}

bool has_backend(const std::string& name) {
  std::lock_guard lock(registry().mutex);
  return registry().factories.count(name) > 0;
}

std::vector<std::string> backend_names() {
  std::lock_guard lock(registry().mutex);
  std::vector<std::string> names;
  for (auto& [name, f] : registry().factories) names.push_back(name);
  return names;
}

std::unique_ptr<Backend> make_backend(const std::string& name) {
  BackendFactory f = nullptr;
  {
    std::lock_guard lock(registry().mutex);
    auto it = registry().factories.find(name);
    if (it != registry().factories.end()) f = it->second;
  }
  if (!f) {
    std::string avail;
    for (auto& n : backend_names()) avail += (avail.empty() ? "" : ", ") + n;
    throw std::invalid_argument("unknown backend '" + name + "' (available: " + avail + ")");
  }
  return f();
}

}  // namespace sn::nn

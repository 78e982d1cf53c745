// The "gl" training backend: fused compute-shader training (shaders/mlp_train.comp) of many
// networks at once. Networks of one architecture train together, one workgroup each, many
// minibatch steps per dispatch with no host round trip in between; architectures train as
// separate specialised programs, epoch by epoch side by side.
//
// llvmpipe ends every loop of a shader invocation after 65,535 iterations in total, silently.
// Before training an architecture the backend measures, with two probe dispatches, how many
// loop iterations a step costs in its compiled kernel, and splits each epoch into dispatches
// that stay within the budget; every dispatch reports the steps it finished and whether the
// limiter cut any of its loops short, checked after the last one (then nothing is committed and
// the chunk is re-run at half the size): a dispatch writes its parameters and moments to a
// staging buffer, copied over the state only when it reports sound.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "nn/trainer.h"

namespace sn::nn {

// What the backend did for one architecture in its last train() call.
struct GlGroupReport {
  std::string arch;                  // spec.describe()
  int nets = 0;
  std::string layout;                // where the kernel keeps its arrays (TrainLayout::describe())
  bool per_net = false;              // the kernel: one network per invocation, or one sample
  long long loop_budget = 0;         // loop iterations left after one step, as the probe counted (0: no limit, or not probed)
  long long loop_cost_per_step = 0;  // 0: the driver does not limit loops
  long long steps_per_dispatch = 0;  // the chunk in use at the end
  long long dispatches = 0;          // training dispatches, re-runs included
  long long cut_dispatches = 0;      // dispatches the loop limiter cut short
  long long divergence_reruns = 0;   // re-runs one step short of a non-finite update
};

struct GlTrainOptions {
  // Steps per dispatch; 0 = as many as the measured loop budget allows. Tests force a larger
  // value to see the backend recover from dispatches the limiter cuts short.
  long long steps_per_dispatch = 0;
  // Shared memory the kernel may use, bytes; 0 = the device's. Tests shrink it to exercise the
  // layouts that keep arrays in a storage buffer.
  std::size_t max_shared_bytes = 0;
  // The kernel: automatic = one invocation per network for small networks on a CPU renderer
  // (nn/mlp_per_net.h), else one per sample; SHADENET_GL_KERNEL=auto|per_sample|per_net forces
  // one where this is automatic. Tests force each on the same networks.
  enum class Kernel { automatic, per_sample, per_net };
  Kernel kernel = Kernel::automatic;
  // Rounds of dispatches (nn/gl_trainer.cpp, run_epoch): automatic = every architecture in one
  // round on a GPU, one at a time on a software renderer. Tests force each on llvmpipe.
  enum class Rounds { automatic, all_architectures, each_architecture };
  Rounds rounds = Rounds::automatic;
};

class GlTrainer : public Backend {
 public:
  explicit GlTrainer(GlTrainOptions options = {}) : options_(options) {}
  std::string name() const override { return "gl"; }
  std::string device() const override;
  // As many as the epoch's orders (one permutation per seed, read by every net of that seed)
  // fit kMaxOrderBytes and, for the per-network kernel, a texture buffer.
  std::size_t seeds_per_call(std::size_t train_rows) const override;
  std::vector<NetResult> train(const std::vector<const Mlp*>& nets, const data::Dataset& data, const TrainConfig& cfg,
                               const Progress& progress) override;
  const std::vector<GlGroupReport>& report() const { return report_; }

 private:
  GlTrainOptions options_;
  std::vector<GlGroupReport> report_;
};

}  // namespace sn::nn

// One network in the cpu backend's working form. The minibatch is the SIMD axis: samples go
// through the network in blocks of 8 (one AVX register per neuron), weight rows are padded to
// a multiple of 8 floats so the gradient and Adam loops run on whole registers. The kernels are
// compiled three times, for x86-64 baseline (SSE2), AVX2+FMA and AVX-512, and the widest the
// CPU has is picked at run time. The AVX-512 kernel fills its 16 lanes with two networks'
// minibatches of 8 (CpuNetPair: a sweep trains many networks of one architecture), with 16
// samples of one network for inference, and with 16 parameters for Adam.
#pragma once
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "nn/activation_expr.h"
#include "nn/loss.h"
#include "nn/mlp_spec.h"
#include "nn/trainer.h"

namespace sn::nn {

// Per-step Adam constants (bias corrections folded in, computed in double for step t).
struct AdamStep {
  float lr, beta1, beta2, eps, inv_c1, inv_c2;  // inv_c = 1 / (1 - beta^t)
  static AdamStep at(const TrainConfig& cfg, long long t);
};

// "avx512", "avx2" or "sse2": the kernel in use (the widest this CPU has; SHADENET_CPU_KERNEL
// in the environment picks another the CPU has).
const char* cpu_kernel_name();
// The kernels this CPU can run, narrowest first.
std::vector<std::string> cpu_kernels_available();
// Switches kernels (tests compare each with the oracle); throws when the CPU lacks it.
void use_cpu_kernel(const std::string& name);

// The cpu code of activation `a` in the kernel in use, over n pre-activations z (the tests
// compare it with the double twins): f(z), and f'(z) as the backward pass gets it (from f(z)
// where the activation allows, else as the forward pass stores it). A user's definition runs
// its translated GLSL (nn/activation_expr.h); throws for one without cpu code.
void cpu_activation(Activation a, float param, const float* z, std::size_t n, float* f, float* df);
// Whether the cpu kernels can run `spec` (every built-in activation can, and a script's whose
// GLSL translates). When not, `without` gets the activation that lacks cpu code.
bool has_cpu_code(const MlpSpec& spec, Activation* without = nullptr);
// A translated activation program over n points z, in the kernel in use: f(z) into out, and
// f'(z) into grad when given (a program translated with its derivative).
void cpu_translated(const ActivationExpr& e, float param, const float* z, std::size_t n, float* out,
                    float* grad = nullptr);

// A minibatch as the training step reads it: blocks of 8 samples, each its inputs then its
// targets, value-major (value i of sample s at [i * 8 + s]), the last block's samples past the
// batch 0. pack_minibatch packs rows[0..batch) of x (inputs wide) and y (outputs wide) into
// mb, minibatch_floats(batch, inputs, outputs) floats (a job packs a run of steps at once).
std::size_t minibatch_floats(int batch, int inputs, int outputs);
void pack_minibatch(const float* x, const float* y, int inputs, int outputs, const uint32_t* rows, int batch,
                    float* mb);

// Its rows are what the first layer reads: spec.width(0) floats each, the inputs already
// encoded when the spec has encodings (nn/encoding.h encode_rows; the cpu trainer encodes a
// dataset once per run).
class CpuNet {
 public:
  CpuNet(const MlpSpec& spec, const float* params);  // params in the shared flat layout
  ~CpuNet();
  CpuNet(const CpuNet&) = delete;
  CpuNet& operator=(const CpuNet&) = delete;

  const MlpSpec& spec() const { return spec_; }
  void get_params(float* flat) const;  // current parameters, shared flat layout
  void set_params(const float* flat);  // also clears the Adam moments
  // The loss gradient of the last step(), shared flat layout (Adam hides a wrong gradient scale,
  // so the tests compare this directly with the oracle).
  void get_gradient(float* flat) const;

  // The loss step() minimises (nn/loss.h; l2 until set).
  void set_loss(const Loss& loss) { loss_ = loss; }

  // The divergence rule's bound on one sample's squared error (summed over outputs; nn/trainer.h).
  void set_sample_limit(float limit) { sample_limit_ = limit; }

  // One Adam step on the packed minibatch mb of `batch` samples (pack_minibatch; width(0)
  // inputs, outputs targets). Returns false, leaving the parameters as they were, when a sample's loss is not
  // finite, a sample's squared error is above the sample limit (why = exploded) or the new
  // parameters are not finite (why = nonfinite). `loss` = the minibatch's loss before the update.
  bool step(const float* mb, int batch, const AdamStep& adam, double* loss, DivergenceKind* why = nullptr);

  // MSE over `count` contiguous rows; mean_loss: the set loss over them.
  double mse(const float* x, const float* y, std::size_t count);
  double mean_loss(const float* x, const float* y, std::size_t count);
  // Outputs for `count` contiguous rows (count x outputs floats).
  void forward(const float* x, std::size_t count, float* out);
  // The forward pass on samples already in the kernel's lane layout (the cpu renderer's,
  // nn/cpu_render.h, which gathers pixels straight into it): `blocks` blocks of 8 samples, input
  // i of sample s of block b at x[(b * inputs + i) * 8 + s]; outputs likewise into y.
  static constexpr int kLanes = 8;
  void forward_lanes(const float* x, std::size_t blocks, float* y);
  // Per hidden layer and unit, over `count` rows: how many samples had the unit active (relu,
  // leaky_relu: output > 0) or saturated (tanh: |a| > 0.99; sigmoid: a < 0.01 or a > 0.99; the
  // other activations: flat, |f'(z)| < 0.01).
  std::vector<std::vector<uint32_t>> unit_counts(const float* x, std::size_t count);

  struct Layout;  // padded offsets, private to cpu_net.cpp

 private:
  friend class CpuNetPair;
  MlpSpec spec_;
  std::unique_ptr<Layout> layout_;
  float* arena_ = nullptr;  // 64-byte aligned: params x2, m, v, grad, activations, scratch
  int cur_ = 0;             // which of the two parameter copies is current
  Loss loss_;
  float sample_limit_ = std::numeric_limits<float>::infinity();
};

// Two networks of one architecture and loss, trained in lock-step by the AVX-512 kernel, 8
// samples of each per register. Each network's parameters, losses and
// verdicts are bit for bit what CpuNet::step gives it alone (the tests hold them to that).
class CpuNetPair {
 public:
  static bool available();  // the kernel in use has the pair mode (avx512)
  static bool can_pair(const CpuNet& a, const CpuNet& b);  // same architecture, activations and loss
  CpuNetPair(const CpuNet& a, const CpuNet& b);  // copies their state: parameters, Adam's moments, sample limits
  ~CpuNetPair();
  CpuNetPair(const CpuNetPair&) = delete;
  CpuNetPair& operator=(const CpuNetPair&) = delete;

  // CpuNet::step for both, network h on its own packed minibatch mb[h] (the same, or each
  // shuffled by its own seed): loss[h], ok[h] and why[h] per network. Returns true when both
  // steps applied; otherwise neither is applied here, and the pair must be split: get(h, net, ok[h]).
  bool step(const float* const mb[2], int batch, const AdamStep& adam, double loss[2], bool ok[2],
            DivergenceKind why[2]);
  // Network h's state (parameters, Adam's moments, the last gradient) into `net`; `written`:
  // the parameters the last, refused step wrote (where network h's own step applied).
  void get(int h, CpuNet& net, bool written = false) const;

 private:
  std::unique_ptr<CpuNet::Layout> layout_;
  float* arena_ = nullptr;  // as CpuNet's, the parameter arrays of the two networks interleaved
  int cur_ = 0;
  Loss loss_;
  float limits_[2] = {};
};

}  // namespace sn::nn

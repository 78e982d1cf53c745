// The double-precision reference every backend is checked against: forward, backward
// (MSE loss, plain backpropagation) and Adam exactly as nn/trainer.h states them, written for
// clarity, not speed. Parameters use the flat layout of nn/mlp_spec.h.
#pragma once
#include <cstddef>
#include <vector>

#include "data/dataset.h"
#include "nn/mlp_spec.h"
#include "nn/trainer.h"

namespace sn::nn::oracle {

// `param`: the activation's parameter (MlpSpec::param).
double activate(Activation a, double param, double z);
// d activation / dz, from the pre-activation z.
double activate_grad(Activation a, double param, double z);

// Activations of every layer for one sample: a[0] = x encoded (spec.width(0) numbers; x itself
// when nothing is encoded), a[layers()] = output; z likewise (z[0] unused). x holds spec.inputs
// raw numbers.
struct Trace {
  std::vector<std::vector<double>> z, a;
};
std::vector<double> forward(const MlpSpec& spec, const std::vector<double>& params, const double* x,
                            Trace* trace = nullptr);

// The loss (nn/loss.h; MSE by default) over `count` samples (rows of x and y) and its gradient
// with respect to every parameter (grad resized to param_count()).
double loss_grad(const MlpSpec& spec, const std::vector<double>& params, const std::vector<const float*>& xs,
                 const std::vector<const float*>& ys, std::vector<double>* grad, const Loss& loss = {});

struct Adam {
  std::vector<double> m, v;
  long long t = 0;
  void step(std::vector<double>& params, const std::vector<double>& grad, const TrainConfig& cfg);
};

// MSE of the network over rows [0, count) of x/y; mean_loss: the same with another loss.
double mse(const MlpSpec& spec, const std::vector<double>& params, const float* x, const float* y, std::size_t count);
double mean_loss(const MlpSpec& spec, const std::vector<double>& params, const float* x, const float* y,
                 std::size_t count, const Loss& loss);

// A whole run as nn/trainer.h defines it (shuffle, minibatches, Adam, curves), in double.
// For tiny datasets in tests: it is slow.
NetResult train(const MlpSpec& spec, const std::vector<float>& params, const data::Dataset& data, const TrainConfig& cfg);

}  // namespace sn::nn::oracle

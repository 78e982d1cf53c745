// Shared by the network unit tests: a spec in one line (leaky_relu slope 0.1).
#pragma once
#include <utility>
#include <vector>

#include "nn/mlp_spec.h"

namespace sn::nn {
inline MlpSpec spec_of(int inputs, std::vector<int> hidden, int outputs, Activation a,
                       Activation out = Activation::linear) {
  MlpSpec s;
  s.inputs = inputs;
  s.hidden = std::move(hidden);
  s.outputs = outputs;
  s.activation = a;
  s.slope = 0.1;
  s.output_activation = out;
  return s;
}
}  // namespace sn::nn

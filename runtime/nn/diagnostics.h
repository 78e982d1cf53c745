// Dead-unit diagnostics, so "sigmoid and ReLU stall at the all-zeros error" (thesis 4.1.4) is
// measured, not guessed. Per hidden layer, over the given rows:
//   relu, leaky_relu: fraction of units never active (output > 0 on no sample);
//   tanh:    fraction of units saturated (|a| > 0.99) on more than 99% of the samples;
//   sigmoid: fraction of units saturated (a < 0.01 or a > 0.99) on more than 99% of the samples.
// The rows `x` are what the first layer reads: encoded (nn/encoding.h encode_rows) when the net
// encodes its inputs, as the cpu kernels take them; the caller encodes once for many nets.
#pragma once
#include <cstddef>
#include <vector>

#include "nn/mlp.h"

namespace sn::nn {

std::vector<double> dead_unit_fractions(const Mlp& net, const float* x, std::size_t count);

// Output channels that no longer depend on the input: the same finite value, to the bit, on
// every one of the rows — a ReLU output pinned at 0 is the thesis' "stall at the all-zeros
// error" (fig. 4.11). -1 for a network without cpu code (an activation whose GLSL does not
// translate) or without rows.
int stuck_outputs(const Mlp& net, const float* x, std::size_t count);

}  // namespace sn::nn

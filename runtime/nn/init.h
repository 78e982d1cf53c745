// Seeded initial parameters. Biases start at 0; weights are uniform in [-limit, limit] with
//   xavier (Glorot & Bengio 2010): limit = sqrt(6 / (fan_in + fan_out))
//   he     (He et al. 2015):       limit = sqrt(6 / fan_in)
//   siren  (Sitzmann et al. 2020, for sin(omega z) layers): the first layer 1 / fan_in, the
//          others sqrt(6 / fan_in) / omega (spec.omega), so that omega z stays in sine's range
// The draw for parameter j is a counter-based hash of (seed, j) (splitmix64), so it is the
// same on every platform and standard library.
#pragma once
#include <cstdint>
#include <vector>

#include "nn/mlp.h"

namespace sn::nn {

// Uniform in [0, 1) from (seed, counter); 53 random bits.
double uniform01(uint64_t seed, uint64_t counter);

std::vector<float> init_params(const MlpSpec& spec, Init init, uint64_t seed);

}  // namespace sn::nn

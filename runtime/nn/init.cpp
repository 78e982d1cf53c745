#include "nn/init.h"

#include <cmath>

namespace sn::nn {

namespace {
uint64_t splitmix64(uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}
}  // namespace

double uniform01(uint64_t seed, uint64_t counter) {
  uint64_t bits = splitmix64(splitmix64(seed) ^ counter);
  return double(bits >> 11) * 0x1.0p-53;
}

std::vector<float> init_params(const MlpSpec& spec, Init init, uint64_t seed) {
  std::vector<float> p(spec.param_count(), 0.0f);
  for (int l = 0; l < spec.layers(); ++l) {
    int in = spec.width(l), out = spec.width(l + 1);
    double limit = std::sqrt(6.0 / (init == Init::xavier ? in + out : in));
    if (init == Init::siren) limit = l == 0 ? 1.0 / in : std::sqrt(6.0 / in) / spec.omega;
    std::size_t off = spec.weight_offset(l);
    for (std::size_t j = 0; j < std::size_t(in) * out; ++j)
      p[off + j] = float((2.0 * uniform01(seed, off + j) - 1.0) * limit);
  }
  return p;
}

}  // namespace sn::nn

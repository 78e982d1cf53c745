#include "nn/diagnostics.h"

#include <cmath>
#include <cstring>

#include "nn/cpu_net.h"

namespace sn::nn {

std::vector<double> dead_unit_fractions(const Mlp& net, const float* x, std::size_t count) {
  // Counted by the cpu backend's kernels: an activation without cpu code has no figure.
  if (!has_cpu_code(net.spec)) return {};
  CpuNet work(net.spec, net.params.data());
  const auto counts = work.unit_counts(x, count);
  const bool relu_like = net.spec.activation == Activation::relu || net.spec.activation == Activation::leaky_relu;
  std::vector<double> fractions;
  for (const auto& layer : counts) {
    int dead = 0;
    for (uint32_t c : layer) dead += relu_like ? c == 0 : double(c) > 0.99 * double(count);
    fractions.push_back(layer.empty() ? 0.0 : double(dead) / double(layer.size()));
  }
  return fractions;
}

int stuck_outputs(const Mlp& net, const float* x, std::size_t count) {
  if (!count || !has_cpu_code(net.spec)) return -1;
  CpuNet work(net.spec, net.params.data());
  const std::size_t outputs = std::size_t(net.spec.outputs);
  std::vector<float> y(count * outputs);
  work.forward(x, count, y.data());
  int stuck = 0;
  for (std::size_t o = 0; o < outputs; ++o) {
    bool same = true;
    for (std::size_t r = 1; r < count && same; ++r) same = std::memcmp(&y[r * outputs + o], &y[o], sizeof(float)) == 0;
    stuck += same && std::isfinite(y[o]);  // NaN everywhere is a diverged net, not a stall
  }
  return stuck;
}

}  // namespace sn::nn

// Fuzz target: a script's activation GLSL translated for the cpu backend (nn/activation_expr.h)
// and run by the kernel in use (nn/cpu_expr.h). Input parts (fuzz_input.h): the GLSL of f, then
// that of f'. A translated program must only name registers it has, and run on any value.
#include <cmath>
#include <stdexcept>

#include "fuzz_input.h"
#include "nn/activation_expr.h"
#include "nn/cpu_net.h"

namespace {
void check(const sn::nn::ActivationExpr& e) {
  const int n = e.registers;
  if (n > sn::nn::kExprRegisters || e.result < 0 || e.result >= n || e.grad >= n) __builtin_trap();
  for (const sn::nn::ExprStep& s : e.steps)
    if (s.dst < 2 || s.dst >= n || s.a >= n || s.b >= n || s.c >= n) __builtin_trap();
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  const std::vector<std::string> parts = sn::fuzz::split_parts(data, size);
  const float z[] = {-1e30f, -88.0f, -3.0f, -1.0f, -0.5f, -0.0f, 0.0f, 1e-40f, 0.25f, 1.0f, 2.0f, 90.0f, 1e30f,
                     INFINITY, -INFINITY, NAN, 7.0f};
  constexpr std::size_t n = sizeof z / sizeof z[0];
  float f[n], g[n];
  try {
    const sn::nn::ActivationExpr alone = sn::nn::translate_activation(parts[0]);
    check(alone);
    sn::nn::cpu_translated(alone, 0.5f, z, n, f);
    if (parts.size() > 1) {
      const sn::nn::ActivationExpr both = sn::nn::translate_activation(parts[0], parts[1]);
      check(both);
      if (both.grad < 0) __builtin_trap();
      sn::nn::cpu_translated(both, 0.5f, z, n, f, g);
    }
  } catch (const std::invalid_argument&) {
  }
  return 0;
}

// The activations shadenet ships, each registered like a user's definition: GLSL of the function
// and of its derivative over the pre-activation z (and, where the output a = f(z) determines it,
// the derivative over a, which saves the backward pass a stored derivative), the double twins
// the oracle uses, and the id of the cpu backend's SIMD code (nn/cpu_activation.h).
// GELU is the tanh form (Hendrycks & Gimpel 2016, eq. 2; PyTorch approximate="tanh").
#include <cmath>

#include "nn/activation.h"

namespace sn::nn {

namespace {

constexpr double kGeluC = 0.7978845608028654;  // sqrt(2 / pi)
constexpr double kGeluK = 0.044715;

double sigmoid(double z) { return 1.0 / (1.0 + std::exp(-z)); }

ActivationDef def(Builtin id, const char* name, std::string glsl, std::string grad, std::string grad_a,
                  std::function<double(double, double)> f, std::function<double(double, double)> df) {
  ActivationDef d;
  d.name = name;
  d.glsl = std::move(glsl);
  d.grad = std::move(grad);
  d.grad_from_output = std::move(grad_a);
  d.origin = std::string("built-in activation ") + name;
  d.f = std::move(f);
  d.df = std::move(df);
  d.simd = int(id);
  return d;
}

}  // namespace

std::vector<ActivationDef> builtin_activations() {
  std::vector<ActivationDef> v;
  v.push_back(def(Builtin::linear, "linear", "z", "vec4(1.0)", "vec4(1.0)", [](double z, double) { return z; },
                  [](double, double) { return 1.0; }));
  v.back().hidden = false;  // a stack of linear layers is one linear map
  v.push_back(def(Builtin::tanh, "tanh", "mlp_tanh(z)", "vec4 t = mlp_tanh(z); return 1.0 - t * t;", "1.0 - a * a",
                  [](double z, double) { return std::tanh(z); },
                  [](double z, double) { return 1.0 - std::tanh(z) * std::tanh(z); }));
  v.push_back(def(Builtin::sigmoid, "sigmoid", "1.0 / (1.0 + exp(-z))", "vec4 s = 1.0 / (1.0 + exp(-z)); return s * (1.0 - s);",
                  "a * (1.0 - a)", [](double z, double) { return sigmoid(z); },
                  [](double z, double) { return sigmoid(z) * (1.0 - sigmoid(z)); }));
  v.push_back(def(Builtin::relu, "relu", "mix(z, vec4(0.0), lessThan(z, vec4(0.0)))",
                  "mix(vec4(0.0), vec4(1.0), greaterThan(z, vec4(0.0)))",
                  "mix(vec4(0.0), vec4(1.0), greaterThan(a, vec4(0.0)))", [](double z, double) { return z > 0 ? z : 0.0; },
                  [](double z, double) { return z > 0 ? 1.0 : 0.0; }));
  v.push_back(def(Builtin::leaky_relu, "leaky_relu", "mix(p * z, z, greaterThan(z, vec4(0.0)))",
                  "mix(vec4(p), vec4(1.0), greaterThan(z, vec4(0.0)))", "mix(vec4(p), vec4(1.0), greaterThan(a, vec4(0.0)))",
                  [](double z, double p) { return z > 0 ? z : p * z; }, [](double z, double p) { return z > 0 ? 1.0 : p; }));
  v.back().param = ActivationParam::slope;
  // sin(omega z): SIREN's layer (Sitzmann et al. 2020) with omega as its w0.
  v.push_back(def(Builtin::sine, "sine", "sin(p * z)", "p * cos(p * z)", "", [](double z, double p) { return std::sin(p * z); },
                  [](double z, double p) { return p * std::cos(p * z); }));
  v.back().param = ActivationParam::omega;
  // log(1 + e^z) = max(z, 0) + log(1 + e^-|z|): no overflow; f' = sigmoid(z) = 1 - e^-a.
  v.push_back(def(Builtin::softplus, "softplus", "max(z, vec4(0.0)) + log(1.0 + exp(-abs(z)))", "1.0 / (1.0 + exp(-z))",
                  "1.0 - exp(-a)", [](double z, double) { return std::max(z, 0.0) + std::log1p(std::exp(-std::fabs(z))); },
                  [](double z, double) { return sigmoid(z); }));
  // (z + sqrt(z^2 + 4)) / 2 (Barron 2021, b = 4), as 2 / (sqrt(z^2 + 4) - z) for z < 0 (no
  // cancellation); f' = a^2 / (a^2 + 1). z^2 overflows float past 1.8e19 (f was inf, f' NaN):
  // z is clamped to 1e18 inside the square root, and f = z beyond it.
  v.push_back(def(Builtin::squareplus, "squareplus",
                  "vec4 c = clamp(z, -1e18, 1e18);\n  vec4 s = sqrt(c * c + 4.0);\n"
                  "  return mix(2.0 / (s - z), mix(0.5 * (z + s), z, greaterThan(z, vec4(1e18))), greaterThanEqual(z, vec4(0.0)));",
                  "vec4 c = clamp(z, -1e18, 1e18); return 0.5 + 0.5 * c / sqrt(c * c + 4.0);",
                  "min(a, vec4(1e18)) * min(a, vec4(1e18)) / (min(a, vec4(1e18)) * min(a, vec4(1e18)) + 1.0)",
                  [](double z, double) { return 0.5 * (z + std::sqrt(z * z + 4.0)); },
                  [](double z, double) { return 0.5 + 0.5 * z / std::sqrt(z * z + 4.0); }));
  // z for z > 0, alpha (e^z - 1) below (Clevert et al. 2016); f' = a + alpha below 0.
  v.push_back(def(Builtin::elu, "elu", "mix(p * (exp(min(z, vec4(0.0))) - 1.0), z, greaterThan(z, vec4(0.0)))",
                  "mix(p * exp(min(z, vec4(0.0))), vec4(1.0), greaterThan(z, vec4(0.0)))",
                  "mix(a + p, vec4(1.0), greaterThan(a, vec4(0.0)))",
                  [](double z, double p) { return z > 0 ? z : p * std::expm1(z); },
                  [](double z, double p) { return z > 0 ? 1.0 : p * std::exp(z); }));
  v.back().param = ActivationParam::alpha;
  // GELU, tanh form (Hendrycks & Gimpel 2016). In f', z is clamped to +-10 where 1 - t^2 is
  // exactly 0 (|u| > 9): z^2 overflowed float past 1.8e19 and made f' = 0 * inf = NaN.
  v.push_back(def(Builtin::gelu, "gelu",
                  "return 0.5 * z * (1.0 + sn_gelu_tanh(z));",
                  "vec4 t = sn_gelu_tanh(z);\nvec4 c = clamp(z, -10.0, 10.0);\n"
                  "return 0.5 * (1.0 + t) + 0.5 * c * (1.0 - t * t) * 0.7978845608028654 * (1.0 + 0.134145 * c * c);",
                  "",
                  [](double z, double) { return 0.5 * z * (1.0 + std::tanh(kGeluC * (z + kGeluK * z * z * z))); },
                  [](double z, double) {
                    const double t = std::tanh(kGeluC * (z + kGeluK * z * z * z));
                    return 0.5 * (1.0 + t) + 0.5 * z * (1.0 - t * t) * kGeluC * (1.0 + 3.0 * kGeluK * z * z);
                  }));
  // z sigmoid(z) (Ramachandran et al. 2017; "silu", Elfwing et al. 2018).
  v.push_back(def(Builtin::swish, "swish", "z / (1.0 + exp(-z))", "vec4 s = 1.0 / (1.0 + exp(-z)); return s * (1.0 + z * (1.0 - s));",
                  "", [](double z, double) { return z * sigmoid(z); },
                  [](double z, double) { return sigmoid(z) * (1.0 + z * (1.0 - sigmoid(z))); }));
  v.back().aliases = {"silu"};
  v.push_back(def(Builtin::exponential, "exponential", "exp(z)", "exp(z)", "a", [](double z, double) { return std::exp(z); },
                  [](double z, double) { return std::exp(z); }));
  return v;
}

}  // namespace sn::nn

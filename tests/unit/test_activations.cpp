// The activation registry (nn/activation.h) and every built-in on every path: the names valid in
// each position, the double twins' derivatives against central differences, the cpu backend's
// SIMD code against the twins over a fine grid (both kernels), and whole networks of each
// activation through the oracle's backward pass against central differences of its loss.
#include <gtest/gtest.h>

#include <cmath>

#include "nn/cpu_net.h"
#include "nn/init.h"
#include "nn/oracle.h"
#include "nn_spec_of.h"

namespace sn::nn {
namespace {

const std::vector<Activation> kHidden = {Activation::tanh,     Activation::sigmoid,    Activation::relu,
                                         Activation::leaky_relu, Activation::sine,     Activation::softplus,
                                         Activation::squareplus, Activation::elu,      Activation::gelu,
                                         Activation::swish,    Activation::exponential};

std::string error_of(const std::string& name, Position p) {
  try {
    parse_activation(name, p, p == Position::hidden ? "activation" : "output_activation");
  } catch (const std::exception& e) {
    return e.what();
  }
  return "(parsed)";
}

TEST(ActivationRegistry, NamesValidInEachPosition) {
  // The built-ins, then what other tests of this program defined (test_cpu_trainer.cpp's).
  std::string hidden = "tanh, sigmoid, relu, leaky_relu, sine, softplus, squareplus, elu, gelu, swish, silu, exponential";
  const auto names = activation_names(Position::hidden);
  for (std::size_t i = 12; i < names.size(); ++i) hidden += ", " + names[i];
  EXPECT_EQ(error_of("sinus", Position::hidden), "unknown activation 'sinus' (valid: " + hidden + ")");
  EXPECT_EQ(error_of("linear", Position::hidden),
            "activation 'linear' cannot be used for hidden layers (valid: " + hidden + ")");
  EXPECT_EQ(error_of("sinus", Position::output), "unknown output_activation 'sinus' (valid: linear, " + hidden + ")");
  EXPECT_EQ(parse_activation("silu"), Activation::swish);
  EXPECT_EQ(parse_activation("linear", Position::output), Activation::linear);
  for (Activation a : kHidden) EXPECT_EQ(parse_activation(activation_name(a)), a);
  // A C++-built spec with linear hidden layers is refused the same way.
  MlpSpec s = spec_of(2, {3}, 1, Activation::linear);
  EXPECT_THROW(s.validate(), std::invalid_argument);
}

TEST(ActivationRegistry, BuiltinNamesCannotBeTakenAndParametersAreChecked) {
  ActivationDef d;
  d.name = "tanh";
  d.glsl = d.grad = "z";
  d.f = d.df = [](double z, double) { return z; };
  EXPECT_THROW(register_activation(d), std::invalid_argument);
  d.name = "Bad Name";
  EXPECT_THROW(register_activation(d), std::invalid_argument);
  MlpSpec s = spec_of(2, {3}, 1, Activation::sine);
  s.omega = 0;
  EXPECT_THROW(s.validate(), std::invalid_argument);
  s.omega = 30;
  EXPECT_NO_THROW(s.validate());
  EXPECT_EQ(s.describe(), "mlp(2 -> 3 -> 1, sine 30)");
  s.activation = Activation::elu;
  s.alpha = std::nan("");
  EXPECT_THROW(s.validate(), std::invalid_argument);
}

// The double twins: f' against central differences of f (away from kinks).
TEST(ActivationTwins, DerivativeMatchesCentralDifferences) {
  for (Activation a : kHidden) {
    const ActivationDef& d = activation_def(a);
    const double p = a == Activation::sine ? 3.0 : a == Activation::elu ? 0.7 : 0.1;
    for (double z = -4.05; z < 4.0; z += 0.1) {
      const double h = 1e-5;
      const double fd = (d.f(z + h, p) - d.f(z - h, p)) / (2 * h);
      EXPECT_NEAR(d.df(z, p), fd, 1e-6 * (1 + std::fabs(fd))) << d.name << " at " << z;
    }
  }
}

// The SIMD code against the twins, on a grid fine enough to cross every polynomial's range
// reduction many times, out to where exp overflows.
TEST(ActivationSimd, MatchesTheDoubleTwinsOnAFineGrid) {
  const std::string saved = cpu_kernel_name();
  std::vector<float> z;
  for (int i = -200000; i <= 200000; ++i) z.push_back(float(i) * 2.5e-4f);  // [-50, 50]
  for (float v : {-1e30f, -1e20f, -1e4f, -300.f, -87.f, 80.f, 88.f, 300.f, 1e4f, 1e19f, 1e20f, 1e30f}) z.push_back(v);
  std::vector<float> f(z.size()), df(z.size());
  for (const auto& k : cpu_kernels_available()) {
    use_cpu_kernel(k);
    for (Activation a : kHidden) {
      const ActivationDef& d = activation_def(a);
      const float p = a == Activation::sine ? 3.0f : a == Activation::elu ? 0.7f : 0.1f;
      cpu_activation(a, p, z.data(), z.size(), f.data(), df.data());
      double worst_f = 0, worst_df = 0;
      for (std::size_t i = 0; i < z.size(); ++i) {
        const double zi = z[i];
        if (a == Activation::sine && std::fabs(p * zi) > 8192) continue;  // past the reduction's range (below)
        const double want = d.f(zi, p), want_d = d.df(zi, p);
        // (std::max below passes a NaN over: gelu's f' was NaN past |z| = 1.8e19, unseen.)
        EXPECT_EQ(std::isnan(df[i]), std::isnan(want_d)) << d.name << " " << k << " f' at " << zi << " = " << df[i];
        if (!(std::fabs(want) <= 3.4028234e38)) {  // exp beyond float: the SIMD code must say inf
          EXPECT_TRUE(std::isinf(f[i])) << d.name << " " << k << " at " << zi;
          continue;
        }
        // sine's argument p z is rounded to float first: an error of half an ulp of it is due.
        const double arg = a == Activation::sine ? 6e-8 * std::fabs(p * zi) : 0.0;
        // Relative to the value's magnitude where it is large (exponential), absolute near 0.
        worst_f = std::max(worst_f, (std::fabs(f[i] - want) - arg) / std::max(1.0, std::fabs(want)));
        worst_df = std::max(worst_df, (std::fabs(df[i] - want_d) - arg * p) / std::max(1.0, std::fabs(want_d)));
      }
      EXPECT_LE(worst_f, 1e-6) << d.name << " " << k;
      EXPECT_LE(worst_df, 5e-6) << d.name << " " << k;  // gelu's f' multiplies tanh's error by ~5
      if (a != Activation::relu && a != Activation::leaky_relu)  // piecewise linear: exact
        EXPECT_GT(worst_f + worst_df, 0.0) << d.name << " " << k << ": float code equals double exactly?";
    }
  }
  std::vector<float> nan = {std::nanf("")}, fn(1), dfn(1);
  for (Activation a : kHidden) {
    cpu_activation(a, 0.1f, nan.data(), 1, fn.data(), dfn.data());
    EXPECT_TRUE(std::isnan(fn[0])) << activation_name(a) << ": NaN must not turn into a number";
  }
  use_cpu_kernel(saved);
}

// tanh and sigmoid saturate exactly in every kernel: beyond tanh's clamp the value is +-1 and the
// derivative 0, whether the kernel's compiler fused the polynomial's multiply-adds or not (the
// AVX kernels' tanh stopped at 1 - 2.4e-7 there, and large inputs trained saturated units).
TEST(ActivationSimd, SaturatedTanhAndSigmoidAreExact) {
  const std::string saved = cpu_kernel_name();
  std::vector<float> z = {8.0139399f, 8.5f, 9.f, 20.f, 1e4f, 1e30f};
  for (std::size_t i = 0, n = z.size(); i < n; ++i) z.push_back(-z[i]);
  std::vector<float> f(z.size()), df(z.size());
  for (const auto& k : cpu_kernels_available()) {
    use_cpu_kernel(k);
    cpu_activation(Activation::tanh, 0, z.data(), z.size(), f.data(), df.data());
    for (std::size_t i = 0; i < z.size(); ++i) {
      EXPECT_EQ(f[i], z[i] > 0 ? 1.0f : -1.0f) << k << " tanh at " << z[i];
      EXPECT_EQ(df[i], 0.0f) << k << " tanh' at " << z[i];
    }
    std::vector<float> z2(z.size());
    for (std::size_t i = 0; i < z.size(); ++i) z2[i] = 2 * z[i];
    cpu_activation(Activation::sigmoid, 0, z2.data(), z2.size(), f.data(), df.data());
    for (std::size_t i = 0; i < z.size(); ++i) {
      EXPECT_EQ(f[i], z[i] > 0 ? 1.0f : 0.0f) << k << " sigmoid at " << z2[i];
      EXPECT_EQ(df[i], 0.0f) << k << " sigmoid' at " << z2[i];
    }
  }
  use_cpu_kernel(saved);
}

// Far beyond the range its reduction is exact for (|p z| > 8192), sine stays in [-1, 1] with a
// finite derivative in every kernel: it gave 13.3 at 1e9 and -inf from 1e10 (its quadrant
// integer overflowed). NaN stays NaN. Up to 8192 it is sin within 2e-7 (the documented range).
TEST(ActivationSimd, SineStaysInRangeForHugeArguments) {
  const std::string saved = cpu_kernel_name();
  std::vector<float> z = {8193.f, 1e5f, 112330.f, 3e7f, 1e9f, 3.4e9f, 1e10f, 1e20f, 3e38f, 8191.5f, 4096.25f};
  for (std::size_t i = 0, n = z.size(); i < n; ++i) z.push_back(-z[i]);
  z.push_back(std::nanf(""));
  std::vector<float> f(z.size()), df(z.size());
  for (const auto& k : cpu_kernels_available()) {
    use_cpu_kernel(k);
    cpu_activation(Activation::sine, 1.0f, z.data(), z.size(), f.data(), df.data());
    for (std::size_t i = 0; i + 1 < z.size(); ++i) {
      EXPECT_TRUE(f[i] >= -1.0f && f[i] <= 1.0f) << k << " sin(" << z[i] << ") = " << f[i];
      EXPECT_TRUE(df[i] >= -1.0f && df[i] <= 1.0f) << k << " cos(" << z[i] << ") = " << df[i];
      if (std::fabs(z[i]) <= 8192) EXPECT_NEAR(f[i], std::sin(double(z[i])), 2e-7) << k << " sin(" << z[i] << ")";
    }
    EXPECT_TRUE(std::isnan(f.back())) << k;
  }
  use_cpu_kernel(saved);
}

// The oracle's backward pass against central differences of its loss, for a network of every
// activation (hidden, and the same activation at the output).
TEST(ActivationOracle, GradientMatchesCentralDifferences) {
  float xs[3][3] = {{0.3f, -0.7f, 0.5f}, {-0.2f, 0.9f, 0.1f}, {0.8f, 0.4f, -0.6f}};
  float ys[3][2] = {{0.2f, 0.7f}, {0.5f, 0.1f}, {0.9f, 0.4f}};
  std::vector<const float*> x = {xs[0], xs[1], xs[2]}, y = {ys[0], ys[1], ys[2]};
  for (Activation a : kHidden) {
    for (Activation out : {Activation::linear, a}) {
      MlpSpec s = spec_of(3, {5, 4}, 2, a, out);
      s.omega = 2.0;
      s.alpha = 0.7;
      auto init = init_params(s, Init::xavier, 3);
      std::vector<double> p(init.begin(), init.end()), g;
      for (std::size_t j = 0; j < p.size(); ++j) p[j] += 0.2 * (uniform01(5, j) - 0.5);  // biases off 0: no kinks
      oracle::loss_grad(s, p, x, y, &g);
      double worst = 0, gmax = 0;
      for (std::size_t j = 0; j < p.size(); ++j) {
        const double h = 1e-6, keep = p[j];
        p[j] = keep + h;
        const double up = oracle::loss_grad(s, p, x, y, nullptr);
        p[j] = keep - h;
        const double down = oracle::loss_grad(s, p, x, y, nullptr);
        p[j] = keep;
        worst = std::max(worst, std::fabs((up - down) / (2 * h) - g[j]));
        gmax = std::max(gmax, std::fabs(g[j]));
      }
      EXPECT_GT(gmax, 1e-3) << s.describe();
      EXPECT_LE(worst, 1e-6 * std::max(1.0, gmax)) << s.describe();
    }
  }
}

}  // namespace
}  // namespace sn::nn

// The training losses (nn/loss.h): the double twins' derivatives and the oracle's backward pass
// against central differences, and the cpu backend's step and validation loss against the oracle
// for every loss, on both SIMD kernels.
#include <gtest/gtest.h>

#include <cmath>

#include "nn/cpu_net.h"
#include "nn/cpu_trainer.h"
#include "nn/init.h"
#include "nn/oracle.h"
#include "nn_spec_of.h"

namespace sn::nn {
namespace {

const Loss kLosses[] = {parse_loss("l2"), parse_loss("l1"), parse_loss("relative_l2"), parse_loss("huber", 0.1)};

TEST(Loss, NamesAndErrors) {
  EXPECT_EQ(kLosses[3].describe(), "huber(delta=0.1)");
  EXPECT_EQ(kLosses[2].describe(), "relative_l2");
  try {
    parse_loss("l3");
    ADD_FAILURE();
  } catch (const std::exception& e) {
    EXPECT_EQ(std::string(e.what()), "unknown loss 'l3' (valid: l2, l1, relative_l2, huber)");
  }
  EXPECT_THROW(parse_loss("huber", 0), std::invalid_argument);
  EXPECT_THROW(parse_loss("huber", std::nan("")), std::invalid_argument);
  // The values the header promises.
  EXPECT_EQ(kLosses[0].value(0.5, 2), 0.25);
  EXPECT_EQ(kLosses[1].value(-0.5, 2), 0.5);
  EXPECT_DOUBLE_EQ(kLosses[2].value(0.5, 2), 0.25 / 4.01);
  EXPECT_DOUBLE_EQ(kLosses[3].value(0.05, 0), 0.5 * 0.05 * 0.05);
  EXPECT_DOUBLE_EQ(kLosses[3].value(-0.5, 0), 0.1 * (0.5 - 0.05));
}

TEST(Loss, DerivativesMatchCentralDifferences) {
  for (const Loss& l : kLosses)
    for (double e = -1.013; e < 1.0; e += 0.05)
      for (double t : {0.0, 0.3, 2.0}) {
        const double h = 1e-6, fd = (l.value(e + h, t) - l.value(e - h, t)) / (2 * h);
        EXPECT_NEAR(l.grad(e, t), fd, 1e-6 * (1 + std::fabs(fd))) << l.describe() << " e " << e << " t " << t;
      }
}

// Rows with targets spread over [0, 1.2] and networks whose errors straddle huber's delta.
struct Rows {
  std::vector<float> x, y;
  std::vector<const float*> xs, ys;
  std::vector<uint32_t> rows;
  explicit Rows(int n) {
    for (int r = 0; r < n; ++r) {
      for (int i = 0; i < 6; ++i) x.push_back(float(2 * uniform01(31, uint64_t(r * 6 + i)) - 1));
      for (int o = 0; o < 3; ++o) y.push_back(float(1.2 * uniform01(32, uint64_t(r * 3 + o))));
    }
    for (int r = 0; r < n; ++r) {
      xs.push_back(&x[std::size_t(r) * 6]);
      ys.push_back(&y[std::size_t(r) * 3]);
      rows.push_back(uint32_t(r));
    }
  }
};

TEST(Loss, OracleGradientMatchesCentralDifferences) {
  Rows d(5);
  MlpSpec s = spec_of(6, {5, 4}, 3, Activation::tanh, Activation::sigmoid);
  auto init = init_params(s, Init::xavier, 4);
  std::vector<double> p(init.begin(), init.end()), g;
  for (const Loss& l : kLosses) {
    oracle::loss_grad(s, p, d.xs, d.ys, &g, l);
    double worst = 0, gmax = 0;
    for (std::size_t j = 0; j < p.size(); ++j) {
      const double h = 1e-6, keep = p[j];
      p[j] = keep + h;
      const double up = oracle::loss_grad(s, p, d.xs, d.ys, nullptr, l);
      p[j] = keep - h;
      const double down = oracle::loss_grad(s, p, d.xs, d.ys, nullptr, l);
      p[j] = keep;
      worst = std::max(worst, std::fabs((up - down) / (2 * h) - g[j]));
      gmax = std::max(gmax, std::fabs(g[j]));
    }
    EXPECT_GT(gmax, 1e-3) << l.describe();
    EXPECT_LE(worst, 1e-6 * std::max(1.0, gmax)) << l.describe();
  }
}

TEST(Loss, CpuStepAndValidationMatchTheOracle) {
  const std::string saved = cpu_kernel_name();
  const std::vector<std::string> kernels = cpu_kernels_available();
  Rows d(13);  // one full block of 8 and a partial one
  MlpSpec s = spec_of(6, {8, 8}, 3, Activation::gelu);
  auto p = init_params(s, Init::xavier, 6);
  TrainConfig cfg;
  cfg.lr = 1e-2;
  for (const Loss& l : kLosses) {
    std::vector<double> pd(p.begin(), p.end()), g;
    const double want_loss = oracle::loss_grad(s, pd, d.xs, d.ys, &g, l);
    oracle::Adam adam;
    adam.step(pd, g, cfg);
    const double want_val = oracle::mean_loss(s, pd, d.x.data(), d.y.data(), 13, l);
    for (const auto& k : kernels) {
      use_cpu_kernel(k);
      CpuNet net(s, p.data());
      net.set_loss(l);
      double got_loss;
      std::vector<float> mb(minibatch_floats(13, 6, 3));
      pack_minibatch(d.x.data(), d.y.data(), 6, 3, d.rows.data(), 13, mb.data());
      ASSERT_TRUE(net.step(mb.data(), 13, AdamStep::at(cfg, 1), &got_loss));
      EXPECT_NEAR(got_loss, want_loss, 1e-6 * want_loss) << l.describe() << " " << k;
      std::vector<float> grad(p.size()), got(p.size());
      net.get_gradient(grad.data());
      double gmax = 0, gerr = 0;
      for (std::size_t j = 0; j < p.size(); ++j) {
        gmax = std::max(gmax, std::fabs(g[j]));
        gerr = std::max(gerr, std::fabs(double(grad[j]) - g[j]));
      }
      EXPECT_LE(gerr, 1e-5 * gmax) << l.describe() << " " << k << ": gradient";
      net.get_params(got.data());
      double worst = 0;
      for (std::size_t j = 0; j < p.size(); ++j) worst = std::max(worst, std::fabs(double(got[j]) - pd[j]));
      EXPECT_LE(worst, 1e-5) << l.describe() << " " << k;
      EXPECT_NEAR(net.mean_loss(d.x.data(), d.y.data(), 13), want_val, 1e-6 * want_val) << l.describe() << " " << k;
    }
  }
  use_cpu_kernel(saved);
}

// A whole run: the curves are in the chosen loss, val_mse stays the MSE, and the losses really
// train differently.
TEST(Loss, CpuRunReportsItsLossAndTheMse) {
  data::Dataset data;
  data.inputs = 6;
  data.outputs = 3;
  Rows tr(160), va(40);
  data.train_x = tr.x;
  data.train_y = tr.y;
  data.val_x = va.x;
  data.val_y = va.y;
  Mlp net(spec_of(6, {8, 8}, 3, Activation::tanh), Init::xavier, 1);
  TrainConfig cfg;
  cfg.epochs = 2;
  cfg.lr = 3e-3;
  std::vector<std::vector<float>> finals;
  for (const Loss& l : kLosses) {
    cfg.loss = l;
    auto got = make_cpu_backend(1)->train({&net}, data, cfg, nullptr)[0];
    auto want = oracle::train(net.spec, net.params, data, cfg);
    EXPECT_EQ(got.loss, l.describe());
    ASSERT_EQ(got.val_loss.size(), 2u);
    EXPECT_EQ(got.train_mse.size(), l.kind == LossKind::l2 ? 2u : 0u);
    for (int e = 0; e < 2; ++e) {
      EXPECT_NEAR(got.train_loss[e], want.train_loss[e], 1e-4 * want.train_loss[e]) << l.describe();
      EXPECT_NEAR(got.val_loss[e], want.val_loss[e], 1e-4 * want.val_loss[e]) << l.describe();
      EXPECT_NEAR(got.val_mse[e], want.val_mse[e], 1e-4 * want.val_mse[e]) << l.describe();
    }
    if (l.kind != LossKind::l2) EXPECT_NE(got.val_loss, got.val_mse) << l.describe();
    finals.push_back(got.final_params);
  }
  for (std::size_t i = 1; i < finals.size(); ++i) EXPECT_NE(finals[i], finals[0]) << kLosses[i].describe();
}

}  // namespace
}  // namespace sn::nn

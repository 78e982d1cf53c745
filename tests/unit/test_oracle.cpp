// The double-precision oracle itself: hand-computed values, gradients against central finite
// differences, one Adam step by formula, and the epoch shuffle.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "nn/init.h"
#include "nn/oracle.h"
#include "nn/train.h"
#include "nn_spec_of.h"
#include "nn/shuffle.h"

namespace sn::nn {
namespace {

TEST(Oracle, ForwardMatchesHandComputation) {
  // 2 -> 1 -> 1, tanh: y = w2 * tanh(w1 . x + b1) + b2
  MlpSpec s = spec_of(2, {1}, 1, Activation::tanh);
  std::vector<double> p = {0.5, -0.25, 0.1, 2.0, -0.3};  // W0 (1x2), b0, W1 (1x1), b1
  double x[2] = {0.8, 0.4};
  double expect = 2.0 * std::tanh(0.5 * 0.8 - 0.25 * 0.4 + 0.1) - 0.3;
  EXPECT_NEAR(oracle::forward(s, p, x)[0], expect, 1e-15);
  s.activation = Activation::leaky_relu;
  p[2] = -1.0;  // z = 0.3 - 1 = -0.7 -> a = 0.1 * -0.7
  EXPECT_NEAR(oracle::forward(s, p, x)[0], 2.0 * 0.1 * -0.7 - 0.3, 1e-15);
}

struct Case {
  Activation hidden, output;
};

class OracleGradient : public ::testing::TestWithParam<Case> {};

TEST_P(OracleGradient, MatchesCentralFiniteDifferences) {
  MlpSpec s = spec_of(5, {7, 4}, 3, GetParam().hidden, GetParam().output);
  auto pf = init_params(s, Init::xavier, 11);
  std::vector<double> p(pf.begin(), pf.end());
  for (std::size_t j = 0; j < p.size(); ++j) p[j] += 0.05 * (uniform01(3, j) - 0.5);  // non-zero biases
  std::vector<float> x(5 * 6), y(3 * 6);
  for (std::size_t j = 0; j < x.size(); ++j) x[j] = float(2 * uniform01(5, j) - 1);
  for (std::size_t j = 0; j < y.size(); ++j) y[j] = float(uniform01(6, j));
  std::vector<const float*> xs, ys;
  for (int n = 0; n < 6; ++n) xs.push_back(&x[n * 5]), ys.push_back(&y[n * 3]);
  std::vector<double> g;
  oracle::loss_grad(s, p, xs, ys, &g);
  ASSERT_EQ(g.size(), s.param_count());
  double worst = 0;
  int checked = 0;
  for (std::size_t j = 0; j < p.size(); ++j) {
    const double h = 1e-6;
    auto q = p;
    q[j] = p[j] + h;
    double up = oracle::loss_grad(s, q, xs, ys, nullptr);
    q[j] = p[j] - h;
    double down = oracle::loss_grad(s, q, xs, ys, nullptr);
    double fd = (up - down) / (2 * h);
    double scale = std::max(std::fabs(fd), std::fabs(g[j]));
    if (scale < 1e-7) {
      EXPECT_NEAR(g[j], fd, 1e-9) << "parameter " << j;
      continue;
    }
    worst = std::max(worst, std::fabs(g[j] - fd) / scale);
    ++checked;
  }
  EXPECT_LE(worst, 1e-3);
  EXPECT_GT(checked, int(p.size()) / 2);  // the check must not be vacuous
}

INSTANTIATE_TEST_SUITE_P(Activations, OracleGradient,
                         ::testing::Values(Case{Activation::tanh, Activation::linear},
                                           Case{Activation::sigmoid, Activation::linear},
                                           Case{Activation::leaky_relu, Activation::linear},
                                           Case{Activation::relu, Activation::linear},
                                           Case{Activation::tanh, Activation::sigmoid}));

TEST(Oracle, AdamStepFollowsTheFormula) {
  TrainConfig c;
  c.lr = 0.01, c.beta1 = 0.8, c.beta2 = 0.9, c.eps = 1e-7;
  oracle::Adam adam;
  std::vector<double> p = {1.0, -2.0}, g = {0.5, -3.0};
  adam.step(p, g, c);
  // t = 1: m/(1-b1) = g and v/(1-b2) = g^2, so the step is lr * g / (|g| + eps).
  EXPECT_NEAR(p[0], 1.0 - 0.01 * 0.5 / (0.5 + 1e-7), 1e-15);
  EXPECT_NEAR(p[1], -2.0 + 0.01 * 3.0 / (3.0 + 1e-7), 1e-15);
  std::vector<double> g2 = {0.1, 1.0};
  adam.step(p, g2, c);
  double m = 0.8 * 0.2 * 0.5 + 0.2 * 0.1, v = 0.9 * 0.1 * 0.25 + 0.1 * 0.01;
  double expect = 1.0 - 0.01 * 0.5 / (0.5 + 1e-7) - 0.01 * (m / (1 - 0.64)) / (std::sqrt(v / (1 - 0.81)) + 1e-7);
  EXPECT_NEAR(p[0], expect, 1e-15);
}

TEST(NetResult, BestEpochIsTheFirstMinimumAndNeverNaN) {
  NetResult r;
  TrainConfig cfg;
  float p[2] = {1, 2};
  EXPECT_FALSE(r.end_epoch(cfg, 10, 0.5, std::nan(""), std::nan(""), p, 2));  // a NaN MSE: exploded
  ASSERT_TRUE(r.diverged.has_value());
  EXPECT_EQ(r.diverged->kind, DivergenceKind::exploded);
  EXPECT_EQ(r.diverged->epoch, 1);
  EXPECT_EQ(r.diverged->step, 10);
  r.end_epoch(cfg, 10, 0.4, 0.3, 0.3, p, 2);
  p[0] = 7;
  r.end_epoch(cfg, 10, 0.3, 0.2, 0.2, p, 2);
  r.end_epoch(cfg, 10, 0.2, 0.2, 0.2, p + 1, 1);  // a tie: the earlier epoch stays
  r.end_epoch(cfg, 10, 0.1, 0.25, 0.25, p, 2);
  EXPECT_EQ(r.best_epoch, 3);
  EXPECT_EQ(r.best_val_mse, 0.2);
  EXPECT_EQ(r.best_params, (std::vector<float>{7, 2}));
  EXPECT_EQ(r.val_mse.size(), 5u);
}

// The loss-explosion rule (nn/trainer.h): above factor x the best so far (the untrained net's
// included) and above the constant predictor's MSE; either alone is not enough.
TEST(DivergenceRule, NeedsBothTheFactorAndTheConstantPredictor) {
  DivergenceRule rule;
  rule.constant_mse = 0.1;
  EXPECT_FALSE(rule.exploded(0.05, 0.0001));  // 500x its best, still better than the mean
  EXPECT_FALSE(rule.exploded(5.0, 0.2));       // worse than the mean, 25x its best
  EXPECT_TRUE(rule.exploded(25.0, 0.2));       // both
  EXPECT_TRUE(rule.exploded(std::nan(""), 0.2));
  EXPECT_TRUE(rule.exploded(INFINITY, 0.2));
  rule.factor = INFINITY;  // off: only a non-finite MSE
  EXPECT_FALSE(rule.exploded(1e30, 0.2));
  EXPECT_TRUE(rule.exploded(std::nan(""), 0.2));
  EXPECT_EQ(rule.sample_limit(0.5, 3), INFINITY);
  DivergenceRule none;  // no constant predictor (a backend called without the job)
  EXPECT_FALSE(none.exploded(1e30, 1e-6));
  EXPECT_EQ(none.sample_limit(0.5, 3), INFINITY);
  // The sample bound: 1e12 x outputs x the larger of the two references.
  rule.factor = 100;
  EXPECT_FLOAT_EQ(rule.sample_limit(0.5, 3), float(1e12 * 3 * 0.5));
  EXPECT_FLOAT_EQ(rule.sample_limit(0.01, 3), float(1e12 * 3 * 0.1));
  EXPECT_FLOAT_EQ(rule.sample_limit(std::nan(""), 1), float(1e12 * 0.1));
  rule.constant_mse = 0;
  EXPECT_EQ(rule.sample_limit(0, 3), INFINITY);  // constant targets, a perfect start: no bound
}

// The untrained net's MSE counts as the best before epoch 1: a slow start far above the mean is
// not an explosion.
TEST(NetResult, ExplosionIsMeasuredFromTheUntrainedNet) {
  TrainConfig cfg;
  cfg.divergence.constant_mse = 1.0;
  float p[1] = {0};
  NetResult slow;
  slow.initial_val_mse = 10000;
  EXPECT_TRUE(slow.end_epoch(cfg, 5, 1, 500, 500, p, 1));
  EXPECT_FALSE(slow.diverged.has_value());
  NetResult blow;
  blow.initial_val_mse = 0.5;
  EXPECT_TRUE(blow.end_epoch(cfg, 5, 1, 0.3, 0.3, p, 1));
  EXPECT_TRUE(blow.end_epoch(cfg, 5, 1, 20, 20, p, 1));  // 67x its best: not yet
  EXPECT_FALSE(blow.end_epoch(cfg, 5, 1, 31, 31, p, 1));
  ASSERT_TRUE(blow.diverged.has_value());
  EXPECT_EQ(blow.diverged->epoch, 3);
  EXPECT_EQ(blow.diverged->step, 5);
  EXPECT_EQ(blow.diverged->kind, DivergenceKind::exploded);
}

TEST(DivergenceRule, ConstantPredictorIsTheValidationMSEAroundTheTrainingMean) {
  sn::data::Dataset d;
  d.inputs = 1;
  d.outputs = 2;
  d.train_x = {0, 0, 0, 0};
  d.train_y = {1, 10, 3, 10, 2, 10, 2, 10};  // means 2 and 10
  d.val_x = {0, 0};
  d.val_y = {4, 10, 2, 12};
  EXPECT_DOUBLE_EQ(constant_predictor_mse(d), (4.0 + 0 + 0 + 4) / 4);
}

TEST(Shuffle, IsAPermutationForEverySize) {
  for (uint32_t n : {1u, 2u, 3u, 5u, 8u, 63u, 64u, 65u, 1000u, 51319u}) {
    for (uint32_t epoch : {0u, 7u}) {
      EpochShuffle perm(42, epoch, n);
      std::vector<char> seen(n, 0);
      for (uint32_t k = 0; k < n; ++k) {
        uint32_t r = perm(k);
        ASSERT_LT(r, n);
        ASSERT_FALSE(seen[r]) << "n " << n << " row " << r << " twice";
        seen[r] = 1;
      }
    }
  }
}

TEST(Shuffle, DependsOnSeedAndEpochAndIsPinned) {
  const uint32_t n = 1000;
  auto first = [&](uint32_t seed, uint32_t epoch) {
    std::vector<uint32_t> v;
    for (uint32_t k = 0; k < 16; ++k) v.push_back(shuffle_index(seed, epoch, k, n));
    return v;
  };
  EXPECT_NE(first(1, 0), first(1, 1));
  EXPECT_NE(first(1, 0), first(2, 0));
  EXPECT_EQ(first(1, 0), first(1, 0));
  // Pinned values (also computed by an independent Python transcription of nn/shuffle.h):
  // the gl kernel and saved experiments rely on this exact permutation.
  EXPECT_EQ(mix32(1u), 0x688990c0u) << std::hex << mix32(1u);
  std::vector<uint32_t> pinned = {shuffle_index(1, 0, 0, n), shuffle_index(1, 0, 1, n), shuffle_index(7, 3, 999, n)};
  EXPECT_EQ(pinned, (std::vector<uint32_t>{624, 35, 51}));
  // Rows are spread out: the first 100 positions hit all ten deciles of 0..999.
  std::vector<int> deciles(10, 0);
  for (uint32_t k = 0; k < 100; ++k) deciles[shuffle_index(1, 0, k, n) / 100]++;
  for (int d : deciles) EXPECT_GT(d, 0);
}

TEST(Init, XavierAndHeLimitsAndSeeds) {
  MlpSpec s = spec_of(6, {13, 6}, 3, Activation::tanh);
  auto a = init_params(s, Init::xavier, 1), b = init_params(s, Init::xavier, 1), c = init_params(s, Init::xavier, 2);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  for (int l = 0; l < s.layers(); ++l) {
    int in = s.width(l), out = s.width(l + 1);
    double limit = std::sqrt(6.0 / (in + out)), maxabs = 0;
    for (int j = 0; j < in * out; ++j) maxabs = std::max(maxabs, std::fabs(double(a[s.weight_offset(l) + j])));
    EXPECT_LE(maxabs, limit);
    EXPECT_GT(maxabs, 0.7 * limit);  // uniform draws reach near the limit
    for (int o = 0; o < out; ++o) EXPECT_EQ(a[s.bias_offset(l) + o], 0.0f);
  }
  auto h = init_params(s, Init::he, 1);
  double maxabs = 0;
  for (int j = 0; j < 6 * 13; ++j) maxabs = std::max(maxabs, std::fabs(double(h[j])));
  EXPECT_LE(maxabs, std::sqrt(6.0 / 6));
  EXPECT_GT(maxabs, std::sqrt(6.0 / 19));  // wider than Xavier's limit for this layer
}

}  // namespace
}  // namespace sn::nn

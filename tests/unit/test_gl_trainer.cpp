// The gl training backend (nn/gl_trainer.h) against the double-precision oracle and the cpu
// backend, for both of its kernels (an invocation per sample, shaders/mlp_train.comp; an
// invocation per network, shaders/mlp_train_per_net.comp): one Adam step, whole curves,
// determinism, llvmpipe's loop limit, divergence, grouping by architecture, networks sharing a
// workgroup, and the storage-buffer fallbacks.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <random>

#include "gl/context.h"
#include "nn/cpu_trainer.h"
#include "nn/gl_trainer.h"
#include "nn/oracle.h"
#include "nn/train.h"

using namespace sn::nn;
using sn::data::Dataset;

namespace {

MlpSpec spec_of(std::vector<int> hidden, Activation act = Activation::tanh) {
  MlpSpec s;
  s.inputs = 6;
  s.hidden = std::move(hidden);
  s.outputs = 3;
  s.activation = act;
  return s;
}

// A Phong-like target of (normal, view): diffuse + a highlight, per colour channel.
Dataset phong_like(std::size_t train, std::size_t val, uint32_t seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<float> g(0.f, 1.f);
  auto unit = [&](float* v) {
    float n = 0;
    for (int i = 0; i < 3; ++i) v[i] = g(rng), n += v[i] * v[i];
    for (int i = 0; i < 3; ++i) v[i] /= std::sqrt(n);
  };
  const float l[3] = {0.48f, 0.64f, 0.6f};
  Dataset d;
  d.inputs = 6;
  d.outputs = 3;
  auto fill = [&](std::vector<float>& x, std::vector<float>& y, std::size_t n) {
    x.resize(n * 6);
    y.resize(n * 3);
    for (std::size_t r = 0; r < n; ++r) {
      float* nv = &x[r * 6];
      unit(nv);
      unit(nv + 3);
      float ndl = nv[0] * l[0] + nv[1] * l[1] + nv[2] * l[2];
      float rv = 0;  // reflect(-l, n) . v
      for (int i = 0; i < 3; ++i) rv += (2 * ndl * nv[i] - l[i]) * nv[3 + i];
      float diff = std::max(ndl, 0.f), spec = std::pow(std::max(rv, 0.f), 8.f);
      y[r * 3 + 0] = 0.1f + 0.7f * diff + 0.4f * spec;
      y[r * 3 + 1] = 0.1f + 0.5f * diff + 0.4f * spec;
      y[r * 3 + 2] = 0.05f + 0.3f * diff + 0.4f * spec;
    }
  };
  fill(d.train_x, d.train_y, train);
  fill(d.val_x, d.val_y, val);
  d.input_names = {"normal", "view"};
  return d;
}

using Kernel = GlTrainOptions::Kernel;

GlTrainOptions with(Kernel k) {
  GlTrainOptions o;
  o.kernel = k;
  return o;
}

// The tests that hold for either kernel run once per kernel.
class GlKernel : public ::testing::TestWithParam<Kernel> {
 protected:
  GlTrainer trainer() const { return GlTrainer(with(GetParam())); }
  // The layout report names the kernel: the test must run the one it is about.
  void expect_kernel(const GlTrainer& gl) const {
    ASSERT_FALSE(gl.report().empty());
    const bool per_net = gl.report()[0].layout.find("one network per invocation") != std::string::npos;
    EXPECT_EQ(per_net, GetParam() == Kernel::per_net) << gl.report()[0].layout;
  }
};

double max_abs_diff(const std::vector<float>& a, const std::vector<float>& b) {
  EXPECT_EQ(a.size(), b.size());
  double m = 0;
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) m = std::max(m, std::abs(double(a[i]) - double(b[i])));
  return m;
}

}  // namespace

INSTANTIATE_TEST_SUITE_P(Kernels, GlKernel, ::testing::Values(Kernel::per_sample, Kernel::per_net),
                         [](const auto& info) { return info.param == Kernel::per_net ? "per_net" : "per_sample"; });

TEST_P(GlKernel, OneAdamStepMatchesOracleWithin1e5) {
  sn::gl::current();
  for (Activation act : {Activation::tanh, Activation::sigmoid, Activation::relu, Activation::leaky_relu}) {
    MlpSpec spec = spec_of({12, 12, 12}, act);
    Mlp net(spec, Init::xavier, 7);
    Dataset data = phong_like(8, 16, 1);  // 8 rows, batch 8: one step per epoch
    TrainConfig cfg;
    cfg.epochs = 1;
    cfg.batch = 8;
    cfg.lr = 1e-2;  // a step large enough to see in every parameter
    GlTrainer gl = trainer();
    auto r = gl.train({&net}, data, cfg, nullptr);
    expect_kernel(gl);
    auto o = oracle::train(spec, net.params, data, cfg);
    ASSERT_EQ(r.size(), 1u);
    EXPECT_EQ(r[0].steps, 1);
    EXPECT_LE(max_abs_diff(r[0].final_params, o.final_params), 1e-5) << activation_name(act);
    EXPECT_GT(max_abs_diff(r[0].final_params, net.params), 5e-3) << "the step changed nothing";
    EXPECT_NEAR(r[0].train_mse[0], o.train_mse[0], 1e-6 * o.train_mse[0]);
    EXPECT_NEAR(r[0].val_mse[0], o.val_mse[0], 1e-5 * o.val_mse[0]);
  }
}

// Every other activation (and output activation), on a smaller network: each is a program of
// its own, and llvmpipe compiles the per-network kernel's straight-line code slowly.
TEST_P(GlKernel, OneAdamStepMatchesOracleForEveryActivation) {
  sn::gl::current();
  const std::pair<Activation, Activation> cases[] = {
      {Activation::sine, Activation::linear},     {Activation::softplus, Activation::softplus},
      {Activation::squareplus, Activation::linear}, {Activation::elu, Activation::elu},
      {Activation::gelu, Activation::gelu},       {Activation::swish, Activation::sine},
      {Activation::exponential, Activation::swish}, {Activation::tanh, Activation::exponential}};
  for (const auto& [act, out] : cases) {
    MlpSpec spec = spec_of({8, 8}, act);
    spec.output_activation = out;
    spec.omega = 2.0;  // sine: away from the plain sin, so that omega's place in the derivative shows
    spec.alpha = 0.7;
    Mlp net(spec, Init::xavier, 7);
    Dataset data = phong_like(8, 16, 1);
    TrainConfig cfg;
    cfg.epochs = 1;
    cfg.batch = 8;
    cfg.lr = 1e-2;
    GlTrainer gl = trainer();
    auto r = gl.train({&net}, data, cfg, nullptr);
    expect_kernel(gl);
    auto o = oracle::train(spec, net.params, data, cfg);
    ASSERT_EQ(r.size(), 1u);
    EXPECT_EQ(r[0].steps, 1) << spec.describe();
    EXPECT_LE(max_abs_diff(r[0].final_params, o.final_params), 1e-5) << spec.describe();
    EXPECT_GT(max_abs_diff(r[0].final_params, net.params), 5e-3) << "the step changed nothing";
    EXPECT_NEAR(r[0].train_mse[0], o.train_mse[0], 1e-5 * o.train_mse[0]) << spec.describe();
    EXPECT_NEAR(r[0].val_mse[0], o.val_mse[0], 1e-5 * o.val_mse[0]) << spec.describe();
  }
}

// Every loss (nn/loss.h): one step against the oracle, the validation loss and MSE beside it.
TEST_P(GlKernel, EveryLossMatchesTheOracle) {
  sn::gl::current();
  MlpSpec spec = spec_of({8, 8}, Activation::tanh);
  spec.output_activation = Activation::sigmoid;
  Mlp net(spec, Init::xavier, 3);
  Dataset data = phong_like(8, 16, 2);
  for (const Loss& loss : {parse_loss("l1"), parse_loss("relative_l2"), parse_loss("huber", 0.1)}) {
    TrainConfig cfg;
    cfg.epochs = 1;
    cfg.batch = 8;
    cfg.lr = 1e-2;
    cfg.loss = loss;
    GlTrainer gl = trainer();
    auto r = gl.train({&net}, data, cfg, nullptr);
    expect_kernel(gl);
    auto o = oracle::train(spec, net.params, data, cfg);
    ASSERT_EQ(r.size(), 1u);
    EXPECT_EQ(r[0].loss, loss.describe());
    EXPECT_LE(max_abs_diff(r[0].final_params, o.final_params), 1e-5) << loss.describe();
    EXPECT_GT(max_abs_diff(r[0].final_params, net.params), 5e-3) << "the step changed nothing";
    EXPECT_NEAR(r[0].train_loss[0], o.train_loss[0], 1e-5 * o.train_loss[0]) << loss.describe();
    EXPECT_NEAR(r[0].val_loss[0], o.val_loss[0], 1e-5 * o.val_loss[0]) << loss.describe();
    EXPECT_NEAR(r[0].val_mse[0], o.val_mse[0], 1e-5 * o.val_mse[0]) << loss.describe();
    EXPECT_NE(r[0].val_loss[0], r[0].val_mse[0]);
    EXPECT_TRUE(r[0].train_mse.empty());
  }
}

// Four steps over two epochs: the minibatches follow the epoch permutation of nn/shuffle.h, so
// the parameters equal the oracle's; another shuffle seed gives other minibatches and other
// parameters.
TEST_P(GlKernel, MinibatchesFollowTheSharedShuffle) {
  sn::gl::current();
  MlpSpec spec = spec_of({10, 10});
  Mlp net(spec, Init::xavier, 2);
  Dataset data = phong_like(16, 8, 12);  // 2 steps per epoch
  TrainConfig cfg;
  cfg.epochs = 2;
  cfg.lr = 1e-2;
  cfg.seed = 21;
  GlTrainer gl = trainer();
  auto r = gl.train({&net}, data, cfg, nullptr)[0];
  expect_kernel(gl);
  auto o = oracle::train(spec, net.params, data, cfg);
  EXPECT_EQ(r.steps, 4);
  EXPECT_LE(max_abs_diff(r.final_params, o.final_params), 1e-5);
  cfg.seed = 22;
  auto other = oracle::train(spec, net.params, data, cfg);
  EXPECT_GT(max_abs_diff(other.final_params, o.final_params), 1e-4) << "the order must matter for this test";
}

// Two epochs of 64 steps: the same curve as the oracle and the cpu backend. Float rounding
// differs between the three (fused multiply-adds, tanh approximations, summation order), and
// Adam's normalised steps let it grow, so curves are compared to 1% relative per epoch.
TEST_P(GlKernel, TwoEpochCurvesMatchOracleAndCpu) {
  sn::gl::current();
  MlpSpec spec = spec_of({8, 8, 8, 8});
  Mlp net(spec, Init::xavier, 3);
  Dataset data = phong_like(512, 128, 2);
  TrainConfig cfg;
  cfg.epochs = 2;
  cfg.lr = 5e-3;
  cfg.seed = 11;
  GlTrainer gl = trainer();
  auto g = gl.train({&net}, data, cfg, nullptr)[0];
  expect_kernel(gl);
  auto c = make_cpu_backend(1)->train({&net}, data, cfg, nullptr)[0];
  auto o = oracle::train(spec, net.params, data, cfg);
  ASSERT_EQ(g.train_mse.size(), 2u);
  ASSERT_EQ(c.train_mse.size(), 2u);
  EXPECT_EQ(g.steps, 2 * 64);
  for (int e = 0; e < 2; ++e) {
    EXPECT_NEAR(g.train_mse[e], o.train_mse[e], 0.01 * o.train_mse[e]) << "epoch " << e + 1;
    EXPECT_NEAR(g.val_mse[e], o.val_mse[e], 0.01 * o.val_mse[e]) << "epoch " << e + 1;
    EXPECT_NEAR(g.train_mse[e], c.train_mse[e], 0.01 * c.train_mse[e]) << "epoch " << e + 1;
    EXPECT_NEAR(g.val_mse[e], c.val_mse[e], 0.01 * c.val_mse[e]) << "epoch " << e + 1;
  }
  // It learned: the second epoch's validation error is well below the untrained one.
  std::vector<double> p0(net.params.begin(), net.params.end());
  double untrained = oracle::mse(spec, p0, data.val_x.data(), data.val_y.data(), data.val_count());
  EXPECT_LT(g.val_mse[1], 0.5 * untrained);
  EXPECT_GE(g.best_epoch, 1);
  EXPECT_EQ(g.best_params.size(), spec.param_count());
}

TEST_P(GlKernel, SameSeedTwiceIsIdenticalAnotherSeedIsNot) {
  sn::gl::current();
  MlpSpec spec = spec_of({6, 6, 6, 6});
  Mlp a(spec, Init::xavier, 1), b(spec, Init::xavier, 2);
  Dataset data = phong_like(400, 50, 3);
  TrainConfig cfg;
  cfg.epochs = 2;
  cfg.seed = 5;
  GlTrainer gl = trainer();
  auto r1 = gl.train({&a, &b}, data, cfg, nullptr);
  expect_kernel(gl);
  auto r2 = gl.train({&a, &b}, data, cfg, nullptr);
  for (int n = 0; n < 2; ++n) {
    EXPECT_EQ(r1[n].final_params, r2[n].final_params);
    EXPECT_EQ(r1[n].train_mse, r2[n].train_mse);
    EXPECT_EQ(r1[n].val_mse, r2[n].val_mse);
  }
  cfg.seed = 6;
  auto r3 = gl.train({&a, &b}, data, cfg, nullptr);
  EXPECT_NE(r1[0].final_params, r3[0].final_params);
}

// llvmpipe ends every loop of an invocation after 65,535 iterations: a run far longer than one
// dispatch can hold must still apply every step it was asked for.
TEST_P(GlKernel, LongRunSplitsIntoDispatchesAndTrainsAsFarAsAsked) {
  sn::gl::current();
  // A per-sample step of a deep network costs hundreds of loop iterations; a per-network step
  // about a minibatch of them, so that kernel gets a long epoch instead.
  const bool per_net = GetParam() == Kernel::per_net;
  MlpSpec spec = spec_of(per_net ? std::vector<int>(4, 6) : std::vector<int>(12, 12));
  Mlp net(spec, Init::xavier, 9);
  const long long steps = per_net ? 8192 : 512;
  Dataset data = phong_like(std::size_t(steps) * 8, 64, 4);
  TrainConfig cfg;
  cfg.epochs = 3;
  GlTrainer gl = trainer();
  auto r = gl.train({&net}, data, cfg, nullptr)[0];
  expect_kernel(gl);
  EXPECT_EQ(r.steps, 3 * steps);
  EXPECT_EQ(r.train_mse.size(), 3u);
  ASSERT_EQ(gl.report().size(), 1u);
  const GlGroupReport& rep = gl.report()[0];
  if (sn::gl::current().info().software) {
    EXPECT_GT(rep.loop_cost_per_step, 0);
    EXPECT_LT(rep.steps_per_dispatch * rep.loop_cost_per_step, 65535);
    EXPECT_GE(rep.dispatches, 3 * ((steps + rep.steps_per_dispatch - 1) / rep.steps_per_dispatch));
  }
  EXPECT_EQ(rep.cut_dispatches, 0);
  // The same run in dispatches far too long for the limiter: each is cut short, committed
  // nowhere, and re-run at half the size until it fits; the result is the same to the bit.
  GlTrainer greedy(GlTrainOptions{1 << 20, 0, GetParam()});
  auto g = greedy.train({&net}, data, cfg, nullptr)[0];
  EXPECT_EQ(g.steps, 3 * steps);
  if (sn::gl::current().info().software) EXPECT_GT(greedy.report()[0].cut_dispatches, 0);
  EXPECT_EQ(g.final_params, r.final_params);
  for (int e = 0; e < 3; ++e) EXPECT_NEAR(g.train_mse[e], r.train_mse[e], 1e-12 * r.train_mse[e]);
}

// Networks share a per-network workgroup eight at a time, each in its own invocation: nine nets
// (the ninth alone in a second workgroup) train exactly as each does alone, and the automatic
// choice on a CPU renderer is this kernel for small networks, the per-sample one for large.
TEST(GlTrainer, PerNetworkInvocationsAreIndependentAndChosenOnCpuRenderers) {
  sn::gl::current();
  MlpSpec spec = spec_of({8, 8});
  std::vector<Mlp> nets;
  for (uint32_t seed = 1; seed <= 9; ++seed) nets.emplace_back(spec, Init::xavier, seed);
  std::vector<const Mlp*> all;
  for (const Mlp& n : nets) all.push_back(&n);
  Dataset data = phong_like(320, 40, 13);
  TrainConfig cfg;
  cfg.epochs = 2;
  GlTrainer gl(with(Kernel::per_net));
  auto together = gl.train(all, data, cfg, nullptr);
  for (std::size_t k : {std::size_t(0), std::size_t(5), std::size_t(8)}) {
    auto alone = gl.train({all[k]}, data, cfg, nullptr)[0];
    EXPECT_EQ(together[k].final_params, alone.final_params) << "net " << k;
    EXPECT_EQ(together[k].val_mse, alone.val_mse) << "net " << k;
  }
  EXPECT_NE(together[0].final_params, together[1].final_params);

  GlTrainer automatic;
  Mlp big(spec_of(std::vector<int>(12, 12)), Init::xavier, 1);
  automatic.train({&nets[0], &big}, data, cfg, nullptr);
  ASSERT_EQ(automatic.report().size(), 2u);
  const bool software = sn::gl::current().info().software;
  EXPECT_EQ(automatic.report()[0].layout.find("one network per invocation") != std::string::npos, software)
      << automatic.report()[0].layout;
  EXPECT_EQ(automatic.report()[1].layout.find("one network per invocation"), std::string::npos)
      << automatic.report()[1].layout;
  Mlp too_big(spec_of(std::vector<int>(12, 12)), Init::xavier, 1);
  EXPECT_THROW(gl.train({&too_big}, data, cfg, nullptr), std::invalid_argument);
}

// Two nets in one dispatch under a learning rate far too large: the ReLU net's activations
// overflow float within a few steps while its neighbour (its ReLUs dead from the start, so only
// the output bias moves) stays finite. The diverged net stops at the same step as on the cpu
// backend (both float; the double oracle would overflow later) with its last finite parameters;
// the neighbour trains exactly as it does alone.
TEST_P(GlKernel, DivergedNetIsFlaggedAndItsNeighbourIsUndisturbed) {
  sn::gl::current();
  // Six layers for the per-sample kernel; two for the per-network one (its size limit).
  MlpSpec spec = spec_of(std::vector<int>(GetParam() == Kernel::per_net ? 2 : 6, 16), Activation::relu);
  Mlp wild(spec, Init::he, 4), calm(spec, Init::he, 5);
  for (int l = 0; l < spec.layers() - 1; ++l)
    for (int j = 0; j < spec.width(l + 1); ++j) calm.biases(l)[j] = -100.f;  // every ReLU dead
  Dataset data = phong_like(256, 32, 5);
  TrainConfig cfg;
  cfg.epochs = 1;
  cfg.lr = 1e15;
  GlTrainer gl = trainer();
  auto r = gl.train({&wild, &calm}, data, cfg, nullptr);
  expect_kernel(gl);
  auto c = make_cpu_backend(1)->train({&wild}, data, cfg, nullptr)[0];
  ASSERT_TRUE(c.diverged.has_value());
  ASSERT_TRUE(r[0].diverged.has_value());
  EXPECT_EQ(r[0].diverged->epoch, c.diverged->epoch);
  EXPECT_EQ(r[0].diverged->step, c.diverged->step);
  EXPECT_GT(r[0].diverged->step, 1);  // it did train before it diverged
  EXPECT_EQ(r[0].steps, c.diverged->step - 1);
  ASSERT_EQ(r[0].final_params.size(), c.final_params.size());
  for (std::size_t i = 0; i < c.final_params.size(); ++i) {
    ASSERT_TRUE(std::isfinite(r[0].final_params[i]));
    ASSERT_NEAR(r[0].final_params[i], c.final_params[i], 1e-5 * std::max(1.f, std::abs(c.final_params[i]))) << i;
  }
  EXPECT_TRUE(r[0].train_mse.empty());  // its epoch did not finish
  EXPECT_FALSE(r[1].diverged.has_value());
  EXPECT_EQ(r[1].steps, 32);
  ASSERT_EQ(r[1].val_mse.size(), 1u);
  EXPECT_TRUE(std::isfinite(r[1].val_mse[0]));
  auto alone = gl.train({&calm}, data, cfg, nullptr)[0];
  EXPECT_EQ(r[1].final_params, alone.final_params);
  EXPECT_EQ(r[1].val_mse, alone.val_mse);
}

// A learning rate that is infinite in float never reaches the kernels as inf (it made the first
// update non-finite): the float uniform refuses it, naming it. (sn.train refuses it before, with
// the option's name: nn/train.cpp.)
TEST_P(GlKernel, LearningRateInfiniteInFloatIsRefused) {
  sn::gl::current();
  MlpSpec spec = spec_of({8, 8});
  Mlp net(spec, Init::xavier, 1);
  Dataset data = phong_like(64, 8, 6);
  TrainConfig cfg;
  cfg.epochs = 2;
  cfg.lr = 1e39;
  GlTrainer gl = trainer();
  try {
    gl.train({&net}, data, cfg, nullptr);
    ADD_FAILURE() << "lr 1e39 trained";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("uniform 'u_lr' (float): 1e+39 is not a finite number"), std::string::npos)
        << e.what();
  }
}

// The divergence rule (nn/trainer.h) flags the same epoch and step on the cpu backend, both gl
// kernels and the oracle: lr = 1e15 puts a sample's squared error near 1e31 at step 2 (before
// float overflow, which the backends' last bits would reach at different steps); lr = 1e3
// explodes the validation MSE by epoch 1's end.
TEST_P(GlKernel, ExplosionIsFlaggedAtTheSameStepAsOnTheCpu) {
  sn::gl::current();
  MlpSpec spec = spec_of({12, 12});
  Mlp net(spec, Init::xavier, 4);
  Dataset data = phong_like(400, 100, 8);
  for (double lr : {1e15, 1e3}) {
    TrainConfig cfg;
    cfg.epochs = 3;
    cfg.lr = lr;
    cfg.divergence.constant_mse = constant_predictor_mse(data);
    GlTrainer gl = trainer();
    auto g = gl.train({&net}, data, cfg, nullptr)[0];
    expect_kernel(gl);
    auto c = make_cpu_backend(1)->train({&net}, data, cfg, nullptr)[0];
    auto o = oracle::train(spec, net.params, data, cfg);
    for (const NetResult* r : {&g, &c, &o}) {
      ASSERT_TRUE(r->diverged.has_value()) << lr;
      EXPECT_EQ(r->diverged->kind, DivergenceKind::exploded) << lr;
      EXPECT_EQ(r->diverged->epoch, 1) << lr;
      EXPECT_EQ(r->diverged->step, lr > 1e10 ? 2 : 50) << lr;
      for (float v : r->final_params) ASSERT_TRUE(std::isfinite(v));
    }
    EXPECT_EQ(g.steps, c.steps);
    if (lr > 1e10)  // one step applied: the same parameters to float's last bits
      for (std::size_t i = 0; i < c.final_params.size(); ++i)
        ASSERT_NEAR(g.final_params[i], c.final_params[i], 1e-5 * std::abs(c.final_params[i])) << i;
  }
}

// A stop flag set before training starts: nothing trains, every net says where it stopped.
TEST_P(GlKernel, StopFlagEndsTheRunAtAStepBoundary) {
  sn::gl::current();
  Mlp a(spec_of({8, 8}), Init::xavier, 1), b(spec_of({6, 6, 6}), Init::xavier, 2);
  Dataset data = phong_like(160, 40, 9);
  std::atomic<bool> stop{false};
  TrainConfig cfg;
  cfg.epochs = 4;
  cfg.stop = &stop;
  GlTrainer gl = trainer();
  int events = 0;
  auto r = gl.train({&a, &b}, data, cfg, [&](const ProgressEvent& e) {
    if (e.epoch == 2 && ++events == 2) stop.store(true);  // after both nets' epoch 2
  });
  for (const NetResult& n : r) {
    ASSERT_TRUE(n.interrupted.has_value());
    EXPECT_EQ(n.interrupted->epoch, 3);  // raw: epoch 3 had not begun (the job writes it 2/20)
    EXPECT_EQ(n.interrupted->step, 0);
    EXPECT_EQ(n.steps, 2 * 20);
    EXPECT_EQ(n.val_mse.size(), 2u);
  }
  auto c = make_cpu_backend(1)->train({&a}, data, cfg, nullptr)[0];  // the flag is still set
  ASSERT_TRUE(c.interrupted.has_value());
  EXPECT_EQ(c.interrupted->epoch, 1);
  EXPECT_EQ(c.steps, 0);
  EXPECT_EQ(c.final_params, a.params);
}

TEST_P(GlKernel, ArchitecturesTrainAsSeparateGroupsLikeAlone) {
  sn::gl::current();
  Mlp a(spec_of({6, 6}), Init::xavier, 1), b(spec_of({10, 10, 10}), Init::xavier, 2), c(spec_of({6, 6}), Init::xavier, 3);
  Dataset data = phong_like(200, 40, 7);
  TrainConfig cfg;
  cfg.epochs = 2;
  GlTrainer gl = trainer();
  auto r = gl.train({&a, &b, &c}, data, cfg, nullptr);
  expect_kernel(gl);
  ASSERT_EQ(gl.report().size(), 2u);
  EXPECT_EQ(gl.report()[0].nets, 2);
  EXPECT_EQ(gl.report()[1].nets, 1);
  auto rb = gl.train({&b}, data, cfg, nullptr)[0];
  auto rc = gl.train({&c}, data, cfg, nullptr)[0];
  EXPECT_EQ(r[1].final_params, rb.final_params);
  EXPECT_EQ(r[2].final_params, rc.final_params);
  EXPECT_EQ(r[2].val_mse, rc.val_mse);
  // Both architectures' dispatches issued in each round (a GPU's way) or one architecture at a
  // time (a software renderer's), in short dispatches so that rounds interleave: the same nets.
  for (auto rounds : {GlTrainOptions::Rounds::all_architectures, GlTrainOptions::Rounds::each_architecture}) {
    GlTrainer forced(GlTrainOptions{5, 0, GetParam(), rounds});
    auto f = forced.train({&a, &b, &c}, data, cfg, nullptr);
    for (std::size_t n = 0; n < 3; ++n) {
      EXPECT_EQ(f[n].final_params, r[n].final_params) << "net " << n;
      EXPECT_EQ(f[n].val_mse, r[n].val_mse) << "net " << n;
    }
    EXPECT_GE(forced.report()[1].dispatches, 2 * 200 / 8 / 5);  // 2 epochs of 25 steps, 5 a dispatch
  }
}

// Nets of one architecture with different shuffle seeds share a group, each reading its seed's
// permutation: one dispatch trains a sweep's seeds together, each net as it trains alone.
TEST_P(GlKernel, NetsOfDifferentSeedsShareAGroupAndTrainAsAlone) {
  sn::gl::current();
  const MlpSpec spec = spec_of({6, 6});
  Mlp a(spec, Init::xavier, 1), b(spec, Init::xavier, 2), c(spec, Init::xavier, 3);
  Dataset data = phong_like(200, 40, 7);
  TrainConfig cfg;
  cfg.epochs = 2;
  cfg.seeds = {5, 9, 5};
  GlTrainer gl = trainer();
  auto r = gl.train({&a, &b, &c}, data, cfg, nullptr);
  expect_kernel(gl);
  ASSERT_EQ(gl.report().size(), 1u);
  EXPECT_EQ(gl.report()[0].nets, 3);
  const Mlp* nets[3] = {&a, &b, &c};
  for (int n = 0; n < 3; ++n) {
    TrainConfig alone = cfg;
    alone.seeds.clear();
    alone.seed = cfg.seeds[std::size_t(n)];
    auto one = gl.train({nets[n]}, data, alone, nullptr)[0];
    EXPECT_EQ(r[std::size_t(n)].final_params, one.final_params) << "net " << n;
    EXPECT_EQ(r[std::size_t(n)].val_mse, one.val_mse) << "net " << n;
  }
  EXPECT_NE(r[0].final_params, r[1].final_params);
  // How many seeds one call takes: Table 4.1's ten on its 51,319 rows; one where a single
  // permutation (2^30 rows, 4 GB) is already beyond 256 MB.
  EXPECT_GE(gl.seeds_per_call(51319), 10u);
  EXPECT_EQ(gl.seeds_per_call(std::size_t(1) << 30), 1u);
}

// The layouts for networks too large for shared memory keep arrays in a storage buffer: same
// arithmetic, so the same parameters.
TEST(GlTrainer, StorageBufferLayoutsTrainLikeSharedMemory) {
  sn::gl::current();
  MlpSpec spec = spec_of({10, 10, 10});
  Mlp net(spec, Init::xavier, 8);
  Dataset data = phong_like(160, 16, 8);
  TrainConfig cfg;
  cfg.epochs = 2;
  GlTrainer shared(with(Kernel::per_sample));
  auto s = shared.train({&net}, data, cfg, nullptr)[0];
  EXPECT_EQ(shared.report()[0].layout.find("storage buffer"), std::string::npos) << shared.report()[0].layout;
  for (std::size_t limit : {std::size_t(3000), std::size_t(1200), std::size_t(64)}) {
    GlTrainer small(GlTrainOptions{0, limit, Kernel::per_sample});
    auto r = small.train({&net}, data, cfg, nullptr)[0];
    EXPECT_NE(small.report()[0].layout.find("storage buffer"), std::string::npos) << small.report()[0].layout;
    EXPECT_LE(max_abs_diff(r.final_params, s.final_params), 1e-6) << small.report()[0].layout;
    EXPECT_EQ(r.steps, s.steps);
  }
}

// The largest network sn.mlp allows (32 hidden layers of 64): nothing fits in shared memory, the
// wide layers' loops stay rolled, a few steps fit a dispatch; it trains like the oracle.
TEST(GlTrainer, LargestArchitectureTrainsLikeOracle) {
  sn::gl::current();
  MlpSpec spec = spec_of(std::vector<int>(32, 64));
  Mlp net(spec, Init::xavier, 1);
  Dataset data = phong_like(32, 8, 10);  // 4 steps
  TrainConfig cfg;
  cfg.epochs = 1;
  cfg.lr = 1e-3;
  GlTrainer gl;
  auto r = gl.train({&net}, data, cfg, nullptr)[0];
  auto o = oracle::train(spec, net.params, data, cfg);
  EXPECT_EQ(r.steps, 4);
  EXPECT_NE(gl.report()[0].layout.find("params+moments+units in a storage buffer"), std::string::npos);
  EXPECT_LE(max_abs_diff(r.final_params, o.final_params), 1e-4);
  EXPECT_GT(max_abs_diff(r.final_params, net.params), 1e-3);
}

// A deep, wide network (64x24) fills llvmpipe's loop budget in a few steps. However an epoch is
// split into dispatches (one step each; as many as the budget allows, what the backend picks first;
// far too many, cut short and re-run at half the size) the result is the same to the bit and the
// oracle's. The kernel used to prove the budget with a counting loop and then write its results
// back in another loop, which the limiter cut in the fullest dispatches: the last layers kept
// their parameters from before the dispatch, reported as sound.
TEST(GlTrainer, DispatchSizesNeverChangeADeepWideNetsTraining) {
  sn::gl::current();
  MlpSpec spec = spec_of(std::vector<int>(24, 64));
  Mlp net(spec, Init::xavier, 1);
  Dataset data = phong_like(160, 16, 11);  // 20 steps
  TrainConfig cfg;
  cfg.epochs = 1;
  cfg.lr = 1e-3;
  GlTrainer single(GlTrainOptions{1, 0, Kernel::per_sample}), fitted, greedy(GlTrainOptions{1 << 20, 0, Kernel::per_sample});
  auto s = single.train({&net}, data, cfg, nullptr)[0];
  auto f = fitted.train({&net}, data, cfg, nullptr)[0];
  auto g = greedy.train({&net}, data, cfg, nullptr)[0];
  EXPECT_EQ(s.steps, 20);
  EXPECT_EQ(f.final_params, s.final_params);
  EXPECT_EQ(g.final_params, s.final_params);
  EXPECT_EQ(f.val_mse, s.val_mse);
  EXPECT_EQ(f.train_mse, s.train_mse);
  EXPECT_EQ(fitted.report()[0].cut_dispatches, 0);
  if (sn::gl::current().info().software) {
    EXPECT_GT(fitted.report()[0].loop_cost_per_step, 0);
    EXPECT_GT(greedy.report()[0].cut_dispatches, 0);
  }
  auto o = oracle::train(spec, net.params, data, cfg);
  EXPECT_LE(max_abs_diff(s.final_params, o.final_params), 1e-4);
  EXPECT_NEAR(s.val_mse[0], o.val_mse[0], 1e-4 * o.val_mse[0]);
}

// A training step that needs more loop iterations than llvmpipe runs per shader invocation (the
// largest network with batch 256) is refused before any training, saying so.
TEST(GlTrainer, StepBeyondTheLoopLimitIsAClearError) {
  sn::gl::current();
  if (!sn::gl::current().info().software) GTEST_SKIP() << "only llvmpipe limits shader loops";
  Mlp net(spec_of(std::vector<int>(32, 64)), Init::xavier, 1);
  Dataset data = phong_like(300, 8, 9);
  TrainConfig cfg;
  cfg.epochs = 1;
  cfg.batch = 256;
  GlTrainer gl;
  try {
    gl.train({&net}, data, cfg, nullptr);
    FAIL() << "expected the loop limit to be reported";
  } catch (const std::runtime_error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("mlp(6 -> 64x32 -> 3, tanh)"), std::string::npos) << m;
    EXPECT_NE(m.find("65,535"), std::string::npos) << m;
    EXPECT_NE(m.find("backend = \"cpu\""), std::string::npos) << m;
  }
}

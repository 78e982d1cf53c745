// The cpu backend against the double-precision oracle: fast tanh, forward, one Adam step, whole
// runs; determinism; divergence; dead-unit diagnostics; the job's input checks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <stdexcept>

#include <xmmintrin.h>

#include "nn/cpu_net.h"
#include "nn/cpu_trainer.h"
#include "nn/diagnostics.h"
#include "nn/fast_tanh.h"
#include "nn/init.h"
#include "nn/oracle.h"
#include "nn_spec_of.h"
#include "nn/train.h"

namespace sn::nn {
using data::Dataset;
namespace {

// A smooth target of 6 inputs (a stand-in for a lighting model): rows split 80/20.
Dataset smooth_dataset(std::size_t rows, uint64_t seed = 9) {
  Dataset d;
  d.inputs = 6;
  d.outputs = 3;
  const std::size_t train = rows * 8 / 10;
  for (std::size_t r = 0; r < rows; ++r) {
    float x[6];
    for (int i = 0; i < 6; ++i) x[i] = float(2 * uniform01(seed, r * 6 + i) - 1);
    float y[3] = {0.5f + 0.4f * x[0] * x[1], 0.5f + 0.4f * std::sin(x[2] + x[3]), 0.3f + 0.2f * x[4] - 0.1f * x[5]};
    auto& X = r < train ? d.train_x : d.val_x;
    auto& Y = r < train ? d.train_y : d.val_y;
    X.insert(X.end(), x, x + 6);
    Y.insert(Y.end(), y, y + 3);
  }
  return d;
}

// rows[0..batch) of d's training rows, packed as the step reads them.
std::vector<float> packed(const Dataset& d, const std::vector<uint32_t>& rows, int batch) {
  std::vector<float> mb(minibatch_floats(batch, d.inputs, d.outputs));
  pack_minibatch(d.train_x.data(), d.train_y.data(), d.inputs, d.outputs, rows.data(), batch, mb.data());
  return mb;
}

struct KernelGuard {  // restores the default kernel
  std::string saved = cpu_kernel_name();
  ~KernelGuard() { use_cpu_kernel(saved); }
};

// Every kernel test below runs each kernel this CPU has (failures name the kernel): the list
// follows the CPU's features, widest last, and the default is the widest.
TEST(CpuKernels, EveryKernelTheCpuHasIsTestedAndTheWidestIsTheDefault) {
  __builtin_cpu_init();
  std::vector<std::string> want = {"sse2"};
  if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) want.push_back("avx2");
  if (want.size() == 2 && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
      __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512bw"))
    want.push_back("avx512");
  EXPECT_EQ(cpu_kernels_available(), want);
  std::string list;
  for (const auto& k : want) list += (list.empty() ? "" : ", ") + k;
  std::printf("cpu kernels tested here: %s\n", list.c_str());
  if (!std::getenv("SHADENET_CPU_KERNEL")) EXPECT_EQ(std::string(cpu_kernel_name()), want.back());
  EXPECT_THROW(use_cpu_kernel("avx1024"), std::invalid_argument);
}

TEST(FastTanh, WithinOneMillionthOfStdTanh) {
  double worst = 0;
  // Every 257th float bit pattern from 0 up to infinity, both signs, plus a fine grid on [-10, 10].
  for (uint32_t bits = 0; bits < 0x7f800000u; bits += 257) {
    float x;
    std::memcpy(&x, &bits, 4);
    for (float s : {x, -x}) worst = std::max(worst, std::fabs(double(fast_tanh(s)) - std::tanh(double(s))));
  }
  for (int i = -100000; i <= 100000; ++i) {
    float x = float(i) * 1e-4f;
    worst = std::max(worst, std::fabs(double(fast_tanh(x)) - std::tanh(double(x))));
  }
  EXPECT_LE(worst, 1e-6);
  EXPECT_GT(worst, 0.0);  // it is an approximation: the comparison is real
  EXPECT_TRUE(std::isnan(fast_tanh(std::nanf(""))));
  EXPECT_EQ(fast_tanh(1e30f), 1.0f);
  EXPECT_EQ(fast_tanh(-1e30f), -1.0f);
}

struct Shape {
  std::vector<int> hidden;
  Activation hidden_act, out_act;
};

class CpuVsOracle : public ::testing::TestWithParam<Shape> {};

TEST_P(CpuVsOracle, ForwardWithin1e5) {
  KernelGuard guard;
  const Shape& sh = GetParam();
  MlpSpec s = spec_of(6, sh.hidden, 3, sh.hidden_act, sh.out_act);
  auto p = init_params(s, Init::xavier, 5);
  for (std::size_t j = 0; j < p.size(); ++j) p[j] += float(0.1 * (uniform01(8, j) - 0.5));
  Dataset d = smooth_dataset(37);  // 29 training rows: not a multiple of 8
  const std::size_t n = d.train_count();
  std::vector<double> pd(p.begin(), p.end());
  std::map<std::string, double> mse;
  for (const auto& k : cpu_kernels_available()) {
    use_cpu_kernel(k);
    CpuNet net(s, p.data());
    mse[k] = net.mse(d.train_x.data(), d.train_y.data(), n);
    std::vector<float> out(n * 3);
    net.forward(d.train_x.data(), n, out.data());
    double worst = 0;
    for (std::size_t r = 0; r < n; ++r) {
      double x[6];
      for (int i = 0; i < 6; ++i) x[i] = d.train_x[r * 6 + i];
      auto y = oracle::forward(s, pd, x);
      for (int o = 0; o < 3; ++o) worst = std::max(worst, std::fabs(double(out[r * 3 + o]) - y[o]));
    }
    EXPECT_LE(worst, 1e-5) << k;
    EXPECT_NEAR(mse[k], oracle::mse(s, pd, d.train_x.data(), d.train_y.data(), n), 1e-6) << k;
  }
  // Validation in 16 lanes (avx512) sums its two halves as the 8-lane kernel sums its blocks:
  // the same number to the bit, so a table does not depend on the kernel that validated it.
  if (mse.count("avx512")) EXPECT_EQ(mse["avx512"], mse["avx2"]);
}

TEST_P(CpuVsOracle, OneAdamStepWithin1e5) {
  KernelGuard guard;
  const Shape& sh = GetParam();
  MlpSpec s = spec_of(6, sh.hidden, 3, sh.hidden_act, sh.out_act);
  auto p = init_params(s, Init::xavier, 6);
  for (std::size_t j = 0; j < p.size(); ++j) p[j] += float(0.1 * (uniform01(8, j) - 0.5));
  Dataset d = smooth_dataset(40);
  TrainConfig cfg;
  cfg.lr = 1e-2;  // large, so that an error in the step shows
  for (int batch : {8, 13, 3}) {
    std::vector<uint32_t> rows;
    std::vector<const float*> xs, ys;
    for (int k = 0; k < batch; ++k) {
      uint32_t r = uint32_t((k * 7 + 3) % d.train_count());
      rows.push_back(r);
      xs.push_back(&d.train_x[r * 6]);
      ys.push_back(&d.train_y[r * 3]);
    }
    std::vector<double> pd(p.begin(), p.end()), g;
    double loss = oracle::loss_grad(s, pd, xs, ys, &g);
    const std::vector<double> g1 = g;
    // Two steps (the second has non-zero moments and bias corrections at t = 2).
    oracle::Adam adam;
    adam.step(pd, g, cfg);
    double loss2 = oracle::loss_grad(s, pd, xs, ys, &g);
    adam.step(pd, g, cfg);
    for (const auto& k : cpu_kernels_available()) {
      use_cpu_kernel(k);
      CpuNet net(s, p.data());
      double l1, l2;
      const std::vector<float> mb = packed(d, rows, batch);
      ASSERT_TRUE(net.step(mb.data(), batch, AdamStep::at(cfg, 1), &l1));
      std::vector<float> grad(p.size());
      net.get_gradient(grad.data());
      double gmax = 0, gerr = 0;
      for (std::size_t j = 0; j < p.size(); ++j) {
        gmax = std::max(gmax, std::fabs(g1[j]));
        gerr = std::max(gerr, std::fabs(double(grad[j]) - g1[j]));
      }
      EXPECT_LE(gerr, 1e-5 * gmax) << k << " batch " << batch << ": gradient";
      ASSERT_TRUE(net.step(mb.data(), batch, AdamStep::at(cfg, 2), &l2));
      EXPECT_NEAR(l1, loss, 1e-6 + 1e-5 * loss) << k << " batch " << batch;
      EXPECT_NEAR(l2, loss2, 1e-6 + 1e-5 * loss2) << k << " batch " << batch;
      std::vector<float> got(p.size());
      net.get_params(got.data());
      double worst = 0, moved = 0;
      for (std::size_t j = 0; j < p.size(); ++j) {
        worst = std::max(worst, std::fabs(double(got[j]) - pd[j]));
        moved = std::max(moved, std::fabs(pd[j] - double(p[j])));
      }
      EXPECT_LE(worst, 1e-5) << k << " batch " << batch;
      EXPECT_GT(moved, 1e-3);  // the step really changed the parameters
    }
  }
}

// A script's activation as sn.activation.define leaves it, its GLSL translated for the cpu
// backend (registered here without the GLSL's own check, which needs a GL context).
Activation translated(const char* name, const char* glsl, const char* grad, double (*f)(double), double (*df)(double)) {
  ActivationDef d;
  d.name = name;
  d.glsl = glsl;
  d.grad = grad;
  d.origin = "test_cpu_trainer.cpp";
  d.f = [f](double z, double) { return f(z); };
  d.df = [df](double z, double) { return df(z); };
  d.cpu_f = std::make_shared<const ActivationExpr>(translate_activation(glsl));
  d.cpu_both = std::make_shared<const ActivationExpr>(translate_activation(glsl, grad));
  return register_activation(std::move(d));
}
Activation softsign() {
  static const Activation a = translated(
      "test_softsign", "x / (1.0 + abs(x))", "vec4 d = 1.0 + abs(x); return 1.0 / (d * d);",
      [](double z) { return z / (1 + std::fabs(z)); }, [](double z) { return 1 / ((1 + std::fabs(z)) * (1 + std::fabs(z))); });
  return a;
}
Activation wiggle() {
  static const Activation a = translated(
      "test_wiggle", "x + 0.3 * sin(2.0 * x)", "1.0 + 0.6 * cos(2.0 * x)", [](double z) { return z + 0.3 * std::sin(2 * z); },
      [](double z) { return 1 + 0.6 * std::cos(2 * z); });
  return a;
}

INSTANTIATE_TEST_SUITE_P(
    Shapes, CpuVsOracle,
    ::testing::Values(Shape{{6, 6, 6, 6}, Activation::tanh, Activation::linear},
                      Shape{{13, 13, 6, 6}, Activation::tanh, Activation::linear},
                      Shape{{1, 9}, Activation::sigmoid, Activation::linear},
                      Shape{{12, 12}, Activation::relu, Activation::linear},
                      Shape{{8, 8, 8}, Activation::leaky_relu, Activation::sigmoid},
                      Shape{{64, 17}, Activation::tanh, Activation::tanh},
                      // The activations whose derivative needs z (kept by the forward pass), and the rest.
                      Shape{{8, 8}, Activation::sine, Activation::linear},
                      Shape{{9, 7}, Activation::gelu, Activation::gelu},
                      Shape{{8, 8}, Activation::swish, Activation::sine},
                      Shape{{8, 8}, Activation::softplus, Activation::softplus},
                      Shape{{10, 6}, Activation::squareplus, Activation::linear},
                      Shape{{8, 8}, Activation::elu, Activation::elu},
                      Shape{{8, 5}, Activation::exponential, Activation::swish},
                      Shape{{12, 12}, Activation::tanh, Activation::exponential},
                      // Activations defined by a script: their translated GLSL, hidden and at the output.
                      Shape{{8, 8}, softsign(), Activation::linear},
                      Shape{{9, 7}, wiggle(), softsign()}));

// The AVX-512 kernel's pair mode: two networks in one register file, each bit for bit what it
// is alone, over steps of every shape (widths not multiples of 8, encoded inputs, activations
// whose derivative needs z, a non-linear output, every loss, a minibatch with dead lanes).
TEST_P(CpuVsOracle, PairedNetsAreBitForBitWhatTheyAreAlone) {
  KernelGuard guard;
  const auto have = cpu_kernels_available();
  if (std::find(have.begin(), have.end(), "avx512") == have.end()) GTEST_SKIP() << "this CPU has no AVX-512";
  use_cpu_kernel("avx512");
  ASSERT_TRUE(CpuNetPair::available());
  const Shape& sh = GetParam();
  MlpSpec s = spec_of(6, sh.hidden, 3, sh.hidden_act, sh.out_act);
  const auto pa = init_params(s, Init::xavier, 11), pb = init_params(s, Init::he, 12);
  Dataset d = smooth_dataset(120);
  TrainConfig cfg;
  cfg.lr = 5e-3;
  for (LossKind loss : {LossKind::l2, LossKind::huber, LossKind::l1, LossKind::relative_l2})
    for (int batch : {8, 13}) {
      CpuNet a(s, pa.data()), b(s, pb.data()), alone_a(s, pa.data()), alone_b(s, pb.data());
      for (CpuNet* n : {&a, &b, &alone_a, &alone_b}) n->set_loss(Loss{loss, 0.05});
      CpuNetPair pair(a, b);
      // Network b reads other rows than a (its own shuffle seed) from step 7 on.
      std::vector<uint32_t> rows(static_cast<std::size_t>(batch), 0u), rows_b = rows;
      for (int t = 1; t <= 12; ++t) {
        for (int k = 0; k < batch; ++k) {
          rows[std::size_t(k)] = uint32_t((k * 7 + t * 5) % d.train_count());
          rows_b[std::size_t(k)] = t > 6 ? uint32_t((k * 11 + t * 3 + 1) % d.train_count()) : rows[std::size_t(k)];
        }
        const std::vector<float> mb = packed(d, rows, batch), mb_b = packed(d, rows_b, batch);
        const float* both[2] = {mb.data(), mb_b.data()};
        double lp[2], la, lb;
        bool ok[2];
        DivergenceKind why[2];
        const AdamStep adam = AdamStep::at(cfg, t);
        ASSERT_TRUE(pair.step(both, batch, adam, lp, ok, why));
        ASSERT_TRUE(alone_a.step(mb.data(), batch, adam, &la));
        ASSERT_TRUE(alone_b.step(mb_b.data(), batch, adam, &lb));
        EXPECT_EQ(lp[0], la) << "step " << t;
        EXPECT_EQ(lp[1], lb) << "step " << t;
      }
      pair.get(0, a);
      pair.get(1, b);
      std::vector<float> got(s.param_count()), want(s.param_count());
      for (auto [n, alone] : {std::pair<CpuNet*, CpuNet*>{&a, &alone_a}, {&b, &alone_b}}) {
        n->get_params(got.data());
        alone->get_params(want.data());
        EXPECT_EQ(got, want) << "loss " << int(loss) << " batch " << batch;
        n->get_gradient(got.data());
        alone->get_gradient(want.data());
        EXPECT_EQ(got, want) << "gradient, loss " << int(loss) << " batch " << batch;
      }
      EXPECT_NE(got, std::vector<float>(got.size(), 0.0f));
    }
}

// One network of a pair refuses its step (its loss is not finite, or a sample is above its
// limit): the other's step applies, as alone, and the refusing one keeps its parameters.
TEST(CpuNetPair, OneNetRefusingLeavesTheOtherAsAlone) {
  KernelGuard guard;
  const auto have = cpu_kernels_available();
  if (std::find(have.begin(), have.end(), "avx512") == have.end()) GTEST_SKIP() << "this CPU has no AVX-512";
  use_cpu_kernel("avx512");
  MlpSpec s = spec_of(6, {8, 8}, 3, Activation::tanh);
  const auto pa = init_params(s, Init::xavier, 1);
  auto pb = init_params(s, Init::xavier, 2);
  Dataset d = smooth_dataset(40);
  std::vector<uint32_t> rows = {0, 3, 6, 9, 12, 15, 18, 21};
  const AdamStep adam = AdamStep::at(TrainConfig{}, 1);
  for (int h = 0; h < 2; ++h)
    for (DivergenceKind kind : {DivergenceKind::nonfinite, DivergenceKind::exploded}) {
      auto bad = pb;
      if (kind == DivergenceKind::nonfinite) bad[s.bias_offset(2)] = std::numeric_limits<float>::infinity();
      CpuNet good(s, pa.data()), worse(s, bad.data()), alone(s, pa.data());
      if (kind == DivergenceKind::exploded) worse.set_sample_limit(1e-6f);
      CpuNetPair pair(h == 0 ? worse : good, h == 0 ? good : worse);  // the refusing one first, then second
      double loss[2], want;
      bool ok[2];
      DivergenceKind why[2];
      const std::vector<float> mb = packed(d, rows, 8);
      const float* both[2] = {mb.data(), mb.data()};
      EXPECT_FALSE(pair.step(both, 8, adam, loss, ok, why));
      EXPECT_FALSE(ok[h]);
      EXPECT_TRUE(ok[1 - h]);
      EXPECT_EQ(why[h], kind);
      ASSERT_TRUE(alone.step(mb.data(), 8, adam, &want));
      EXPECT_EQ(loss[1 - h], want);
      pair.get(1 - h, good, true);
      pair.get(h, worse, false);
      std::vector<float> got(s.param_count()), expect(s.param_count());
      good.get_params(got.data());
      alone.get_params(expect.data());
      EXPECT_EQ(got, expect);
      worse.get_params(got.data());
      EXPECT_EQ(got, bad);
    }
}

// The kernels flush denormals to zero (a relu net's decaying Adam moments took the slow path),
// every kernel alike, and leave the caller's floating-point mode as it was.
TEST(CpuNet, KernelsFlushDenormalsAndRestoreTheCallersMode) {
  KernelGuard guard;
  MlpSpec s = spec_of(6, {8}, 3, Activation::leaky_relu);
  std::vector<float> p(s.param_count(), 0.0f);
  p[s.weight_offset(1)] = 1e-20f;  // output 0 = 1e-20 x hidden unit 0
  p[s.weight_offset(0)] = 1.0f;    // hidden unit 0 = input 0
  const float x[6] = {1e-20f, 0, 0, 0, 0, 0};
  // The mode: rounding, FTZ, DAZ and the exception masks, not the sticky exception flags (bits
  // 0-5), which any inexact operation before the kernel sets.
  const auto mode_of = [](unsigned csr) { return csr & ~0x3Fu; };
  const unsigned mode = mode_of(_mm_getcsr());
  for (const auto& k : cpu_kernels_available()) {
    use_cpu_kernel(k);
    CpuNet net(s, p.data());
    float out[3] = {1, 1, 1};
    net.forward(x, 1, out);
    EXPECT_EQ(out[0], 0.0f) << k << ": 1e-40 is a denormal";
    EXPECT_EQ(mode_of(_mm_getcsr()), mode) << k;
  }
  volatile float tiny = 1e-20f;
  EXPECT_GT(tiny * tiny, 0.0f);  // this thread still computes denormals
}

TEST(CpuTrainer, TwoEpochCurvesMatchTheOracle) {
  KernelGuard guard;
  MlpSpec s = spec_of(6, {8, 8}, 3, Activation::tanh);
  Mlp net(s, Init::xavier, 3);
  Dataset d = smooth_dataset(250);
  TrainConfig cfg;
  cfg.epochs = 2;
  cfg.batch = 8;
  cfg.lr = 5e-3;
  cfg.seed = 4;
  NetResult want = oracle::train(s, net.params, d, cfg);
  ASSERT_EQ(want.val_mse.size(), 2u);
  for (const auto& k : cpu_kernels_available()) {
    use_cpu_kernel(k);
    auto got = make_cpu_backend(1)->train({&net}, d, cfg, nullptr)[0];
    ASSERT_EQ(got.val_mse.size(), 2u);
    EXPECT_EQ(got.steps, want.steps);
    for (int e = 0; e < 2; ++e) {
      EXPECT_NEAR(got.train_mse[e], want.train_mse[e], 1e-4 * want.train_mse[e]) << k << " epoch " << e;
      EXPECT_NEAR(got.val_mse[e], want.val_mse[e], 1e-4 * want.val_mse[e]) << k << " epoch " << e;
    }
    EXPECT_LT(want.val_mse[1], want.val_mse[0]);  // it trains
  }
}

TEST(CpuTrainer, SameSeedSameCurvesWhateverTheGrouping) {
  Dataset d = smooth_dataset(400);
  MlpSpec a = spec_of(6, {6, 6, 6, 6}, 3, Activation::tanh), b = spec_of(6, {13, 6}, 3, Activation::sigmoid);
  Mlp n1(a, Init::xavier, 1), n2(b, Init::he, 2), n3(a, Init::xavier, 3);
  TrainConfig cfg;
  cfg.epochs = 3;
  cfg.lr = 2e-3;
  auto together = make_cpu_backend(2)->train({&n1, &n2, &n3}, d, cfg, nullptr);
  auto again = make_cpu_backend(2)->train({&n1, &n2, &n3}, d, cfg, nullptr);
  auto alone = make_cpu_backend(1)->train({&n2}, d, cfg, nullptr);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(together[i].train_mse, again[i].train_mse);
    EXPECT_EQ(together[i].val_mse, again[i].val_mse);
    EXPECT_EQ(together[i].final_params, again[i].final_params);
  }
  EXPECT_EQ(together[1].val_mse, alone[0].val_mse);
  EXPECT_EQ(together[1].final_params, alone[0].final_params);
  cfg.seed = 2;  // another shuffle, another curve
  auto other = make_cpu_backend(2)->train({&n1}, d, cfg, nullptr);
  EXPECT_NE(other[0].train_mse, together[0].train_mse);
}

// A job's minibatches packed once per shuffle and shared, or by each net (a chunk of steps at a
// time, where the shared ones would take too much memory), train the same to the bit: two seeds,
// pairs and a net alone, encoded inputs (other rows), a batch with dead lanes, and epochs whose
// steps (61) are no multiple of a chunk's.
TEST(CpuTrainer, SharedOrOwnPackedMinibatchesTrainTheSame) {
  Dataset d = smooth_dataset(616);
  MlpSpec a = spec_of(6, {6, 6}, 3, Activation::tanh);
  MlpSpec e = a;
  e.encodings = {default_encoding(Encoding::frequency, "view", 3, 3)};
  Mlp n1(a, Init::xavier, 1), n2(a, Init::xavier, 2), n3(a, Init::xavier, 3), n4(e, Init::xavier, 4);
  TrainConfig cfg;
  cfg.epochs = 2;
  cfg.batch = 8;
  cfg.lr = 2e-3;
  cfg.seeds = {5, 6, 5, 6};
  for (int batch : {8, 13}) {
    cfg.batch = batch;
    auto shared = make_cpu_backend(1)->train({&n1, &n2, &n3, &n4}, d, cfg, nullptr);
    auto own = make_cpu_backend(1, 0)->train({&n1, &n2, &n3, &n4}, d, cfg, nullptr);
    for (int i = 0; i < 4; ++i) {
      ASSERT_EQ(shared[i].val_mse.size(), 2u);
      EXPECT_EQ(shared[i].train_mse, own[i].train_mse) << "net " << i << " batch " << batch;
      EXPECT_EQ(shared[i].val_mse, own[i].val_mse) << "net " << i << " batch " << batch;
      EXPECT_EQ(shared[i].final_params, own[i].final_params) << "net " << i << " batch " << batch;
    }
    EXPECT_NE(shared[0].train_mse, shared[1].train_mse);  // the seeds shuffle differently
  }
}

TEST(CpuTrainer, LearnsFarBelowAConstantPredictor) {
  Dataset d = smooth_dataset(4000);
  // The best constant predictor (the mean of each output) has MSE = variance of the targets.
  double var = 0;
  for (int o = 0; o < 3; ++o) {
    double mean = 0, sq = 0;
    std::size_t n = d.val_count();
    for (std::size_t r = 0; r < n; ++r) mean += d.val_y[r * 3 + o];
    mean /= double(n);
    for (std::size_t r = 0; r < n; ++r) sq += (d.val_y[r * 3 + o] - mean) * (d.val_y[r * 3 + o] - mean);
    var += sq / double(n) / 3;
  }
  Mlp net(spec_of(6, {12, 12}, 3, Activation::tanh), Init::xavier, 1);
  TrainJob job;
  job.nets = {&net};
  job.data = &d;
  job.config.epochs = 20;
  job.config.lr = 3e-3;
  job.config.beta1 = 0.9;
  job.config.beta2 = 0.999;
  auto r = train(job).nets[0];
  EXPECT_LT(r.best_val_mse, 0.05 * var) << "constant predictor " << var;
  EXPECT_LT(r.val_mse.back(), r.val_mse.front());
  EXPECT_EQ(r.best_val_mse, *std::min_element(r.val_mse.begin(), r.val_mse.end()));
  EXPECT_EQ(r.val_mse[r.best_epoch - 1], r.best_val_mse);
  EXPECT_EQ(net.trained_steps, uint64_t(20 * (d.train_count() / 8)));
  EXPECT_GT(r.sample_steps_per_s, 0.0);
}

TEST(CpuTrainer, DivergedNetStopsWithFiniteWeightsOthersGoOn) {
  Dataset d = smooth_dataset(200);
  MlpSpec s = spec_of(6, {6, 6}, 3, Activation::tanh);
  Mlp good(s, Init::xavier, 1), bad(s, Init::xavier, 2), blowup(s, Init::xavier, 3);
  // Outputs of 1e20: the squared error overflows float at the first step.
  for (int o = 0; o < 3; ++o) bad.biases(2)[o] = 1e20f;
  TrainConfig cfg;
  cfg.epochs = 2;
  auto r = make_cpu_backend(2)->train({&good, &bad}, d, cfg, nullptr);
  EXPECT_FALSE(r[0].diverged);
  EXPECT_EQ(r[0].val_mse.size(), 2u);
  ASSERT_TRUE(r[1].diverged);
  EXPECT_EQ(r[1].diverged->epoch, 1);
  EXPECT_EQ(r[1].diverged->step, 1);
  EXPECT_EQ(r[1].final_params, bad.params);  // the step was not applied
  EXPECT_TRUE(r[1].val_mse.empty());
  // A huge learning rate: weights grow until a later step overflows; the last finite ones stay.
  cfg.lr = 1e30;
  auto big = make_cpu_backend(1)->train({&blowup}, d, cfg, nullptr)[0];
  ASSERT_TRUE(big.diverged);
  EXPECT_GE(big.diverged->step, 2);
  EXPECT_EQ(big.steps, big.diverged->step - 1);
  for (float v : big.final_params) ASSERT_TRUE(std::isfinite(v));
  EXPECT_NE(big.final_params, blowup.params);
}

TEST(Diagnostics, DeadReluAndSaturatedTanhUnits) {
  Dataset d = smooth_dataset(300);
  Mlp relu(spec_of(6, {8, 8}, 3, Activation::relu), Init::he, 1);
  for (int o = 0; o < 8; ++o) relu.biases(0)[o] = -100.0f;  // layer 1 never fires
  auto f = dead_unit_fractions(relu, d.val_x.data(), d.val_count());
  ASSERT_EQ(f.size(), 2u);
  EXPECT_EQ(f[0], 1.0);
  EXPECT_EQ(f[1], 1.0);  // fed only zeros, layer 2 is left with its biases (0): never > 0
  Mlp tanh_net(spec_of(6, {8, 4}, 3, Activation::tanh), Init::xavier, 1);
  auto calm = dead_unit_fractions(tanh_net, d.val_x.data(), d.val_count());
  EXPECT_EQ(calm, (std::vector<double>{0.0, 0.0}));
  for (int o = 0; o < 4; ++o) tanh_net.biases(1)[o] = (o % 2 ? 50.0f : -50.0f);  // layer 2 pinned at +-1
  for (int o = 0; o < 2; ++o) tanh_net.biases(0)[o] = 50.0f;                       // 2 of 8 in layer 1
  auto sat = dead_unit_fractions(tanh_net, d.val_x.data(), d.val_count());
  EXPECT_EQ(sat, (std::vector<double>{0.25, 1.0}));
}

// Output channels constant over the rows: all three behind a dead layer, one ReLU output
// pinned at 0 by its bias, none in a live network.
TEST(Diagnostics, StuckOutputChannels) {
  Dataset d = smooth_dataset(300);
  Mlp dead(spec_of(6, {8}, 3, Activation::relu), Init::he, 1);
  for (int o = 0; o < 8; ++o) dead.biases(0)[o] = -100.0f;
  EXPECT_EQ(stuck_outputs(dead, d.val_x.data(), d.val_count()), 3);
  MlpSpec s = spec_of(6, {8}, 3, Activation::relu);
  s.output_activation = Activation::relu;
  Mlp pinned(s, Init::he, 1);
  EXPECT_EQ(stuck_outputs(pinned, d.val_x.data(), d.val_count()), 0);
  pinned.biases(1)[1] = -100.0f;  // output 2 below 0 on every row: ReLU gives exactly 0
  EXPECT_EQ(stuck_outputs(pinned, d.val_x.data(), d.val_count()), 1);
  EXPECT_EQ(stuck_outputs(pinned, d.val_x.data(), 0), -1);
  pinned.biases(1)[0] = std::numeric_limits<float>::quiet_NaN();  // NaN on every row: diverged, not stuck
  EXPECT_EQ(stuck_outputs(pinned, d.val_x.data(), d.val_count()), 1);
}

std::string job_error(TrainJob job) {
  try {
    validate(job);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(TrainJob, RejectsBadInputBeforeAnyWork) {
  Dataset d = smooth_dataset(50);
  Mlp net(spec_of(6, {6}, 3, Activation::tanh), Init::xavier, 1);
  Mlp five(spec_of(5, {6}, 3, Activation::tanh), Init::xavier, 1);
  TrainJob job;
  job.nets = {&net};
  job.data = &d;
  EXPECT_EQ(job_error(job), "(no error)");
  job.config.batch = 41;
  EXPECT_EQ(job_error(job), "batch 41 is larger than the training set (40 rows)");
  job.config.batch = 8;
  job.nets = {&net, &five};
  EXPECT_EQ(job_error(job), "net 2 (mlp(5 -> 6 -> 3, tanh)) reads 5 inputs but the dataset has 6");
  job.nets = {&net, &net};
  EXPECT_EQ(job_error(job), "net 2 is the same network as net 1");
  job.nets = {&net};
  Dataset nan = d;
  nan.train_x[3 * 6 + 4] = std::nanf("");
  job.data = &nan;
  EXPECT_EQ(job_error(job), "dataset: training input row 4 column 5 is NaN");
  job.data = &d;
  job.config.beta2 = 1.0;
  EXPECT_EQ(job_error(job),
            "adam beta2 must be in [0, 1) as a float (the kernels run in float; the largest is 0.99999994), got 1");
  // Settings that round to 1 or 0 in float trained nothing or blew up without a word.
  job.config.beta2 = 0.99999999;
  EXPECT_EQ(job_error(job), "adam beta2 must be in [0, 1) as a float (the kernels run in float; the largest is "
                            "0.99999994), got 0.99999999");
  job.config.beta2 = 0.9;
  const double lr0 = job.config.lr;
  for (double lr : {1e-50, 1e39}) {
    job.config.lr = lr;
    EXPECT_EQ(job_error(job).rfind("adam lr must be a normal float (the kernels run in float), 1.1754944e-38 to "
                                   "3.4028235e38, got ", 0), 0u) << lr;
  }
  job.config.lr = lr0;
  job.backend = "vulkan";
  try {
    train(job);
    ADD_FAILURE() << "unknown backend accepted";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("unknown backend 'vulkan' (available: cpu"), std::string::npos) << e.what();
  }
  EXPECT_EQ(net.trained_steps, 0u);
}

TEST(TrainJob, KeepBestOrLastAndCommit) {
  Dataset d = smooth_dataset(300);
  d.input_names = {"normal", "view"};
  Mlp last(spec_of(6, {8, 8}, 3, Activation::tanh), Init::xavier, 1), best = last;
  TrainJob job;
  job.data = &d;
  job.config.epochs = 4;
  job.config.lr = 0.05;  // noisy, so the best epoch is not always the last
  job.nets = {&last};
  job.backend = "cpu";
  auto v0 = last.version;
  auto r = train(job);
  EXPECT_EQ(r.backend, "cpu");
  EXPECT_EQ(last.params, r.nets[0].final_params);
  EXPECT_EQ(last.best_params, r.nets[0].best_params);
  EXPECT_GT(last.version, v0);
  EXPECT_EQ(last.input_names, d.input_names);
  job.nets = {&best};
  job.keep = Keep::best;
  auto rb = train(job);
  EXPECT_EQ(best.params, rb.nets[0].best_params);
  EXPECT_EQ(rb.nets[0].best_params, r.nets[0].best_params);  // same run, same snapshot
  ASSERT_TRUE(last.restore_best());
  EXPECT_EQ(last.params, best.params);
}

}  // namespace
}  // namespace sn::nn

// Input encodings (nn/encoding.h): the registry and its checks, the double twins against values
// worked out by hand, the GLSL every gl path runs against the twins, and networks that encode
// their inputs against the double-precision oracle on both backends: forward (cpu kernels, gl
// compute shader) and one Adam step (cpu, gl per-sample and per-network kernels); the spec's
// description and grouping.
#include <gtest/gtest.h>

#include <cmath>

#include "gl/context.h"
#include "nn/cpu_net.h"
#include "nn/cpu_trainer.h"
#include "nn/encoding.h"
#include "nn/encoding_define.h"
#include "nn/gl_forward.h"
#include "nn/gl_trainer.h"
#include "nn/init.h"
#include "nn/oracle.h"

namespace sn::nn {
using data::Dataset;
namespace {

constexpr double kPi = 3.14159265358979323846;

InputEncoding enc(Encoding kind, const std::string& input, int offset, int width, int n = -1) {
  InputEncoding e = default_encoding(kind, input, offset, width);
  if (n >= 0) e.n = n;
  return e;
}

// normal (3), view (3), uv (2): 8 raw inputs.
MlpSpec spec_with(std::vector<InputEncoding> encodings, std::vector<int> hidden = {8, 8},
                  Activation act = Activation::tanh) {
  MlpSpec s;
  s.inputs = 8;
  s.encodings = std::move(encodings);
  s.hidden = std::move(hidden);
  s.outputs = 3;
  s.activation = act;
  return s;
}

// Rows of (unit normal, unit view, uv in [0, 1]) and a smooth target with texture-like detail.
Dataset rows_of(std::size_t train, std::size_t val, uint64_t seed) {
  Dataset d;
  d.inputs = 8;
  d.outputs = 3;
  d.input_names = {"normal", "view", "uv"};
  for (std::size_t r = 0; r < train + val; ++r) {
    float x[8];
    for (int g = 0; g < 2; ++g) {
      double v[3], n = 0;
      for (int i = 0; i < 3; ++i) v[i] = 2 * uniform01(seed, r * 16 + std::size_t(g * 3 + i)) - 1, n += v[i] * v[i];
      for (int i = 0; i < 3; ++i) x[g * 3 + i] = float(v[i] / std::sqrt(n));
    }
    x[6] = float(uniform01(seed, r * 16 + 7));
    x[7] = float(uniform01(seed, r * 16 + 8));
    const float y[3] = {0.5f + 0.3f * float(std::sin(12 * x[6])) * x[2], 0.4f + 0.2f * x[3] * x[7],
                        0.3f + 0.2f * float(std::cos(9 * x[7]))};
    auto& X = r < train ? d.train_x : d.val_x;
    auto& Y = r < train ? d.train_y : d.val_y;
    X.insert(X.end(), x, x + 8);
    Y.insert(Y.end(), y, y + 3);
  }
  return d;
}

// One case per built-in encoding (with a non-default option where it has one), the uv or the
// normal encoded, and one with several groups.
struct Case {
  const char* name;
  std::vector<InputEncoding> encodings;
};
std::vector<Case> cases() {
  InputEncoding freq_raw = enc(Encoding::frequency, "uv", 6, 2, 5);
  InputEncoding tri_raw = enc(Encoding::triangle_wave, "uv", 6, 2, 7);
  tri_raw.include_input = true;
  InputEncoding freq_no_raw = enc(Encoding::frequency, "uv", 6, 2, 12);
  freq_no_raw.include_input = false;
  InputEncoding blob_view = enc(Encoding::oneblob, "view", 3, 3, 12);
  blob_view.lo = -1.2, blob_view.hi = 1.1;
  return {
      {"frequency", {freq_raw}},
      {"frequency_high_bands_no_input", {freq_no_raw}},
      {"oneblob", {enc(Encoding::oneblob, "uv", 6, 2, 16)}},
      {"oneblob_range", {blob_view}},
      {"sh1", {enc(Encoding::sh, "normal", 0, 3, 1)}},
      {"sh4", {enc(Encoding::sh, "normal", 0, 3, 4)}},
      {"triangle_wave", {tri_raw}},
      {"identity", {enc(Encoding::identity, "view", 3, 3)}},
      {"several", {enc(Encoding::sh, "normal", 0, 3, 3), enc(Encoding::sh, "view", 3, 3, 2), freq_raw}},
  };
}

double max_diff(const std::vector<float>& a, const std::vector<double>& b) {
  EXPECT_EQ(a.size(), b.size());
  double m = 0;
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) m = std::max(m, std::fabs(double(a[i]) - b[i]));
  return m;
}

}  // namespace

TEST(EncodingRegistry, NamesAndErrors) {
  EXPECT_EQ(encoding_names(), (std::vector<std::string>{"identity", "frequency", "oneblob", "sh", "triangle_wave"}));
  try {
    parse_encoding("fourier");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "unknown encoding 'fourier' (valid: identity, frequency, oneblob, sh, triangle_wave)");
  }
  auto fails = [](InputEncoding e, const std::string& part) {
    try {
      check(e);
      ADD_FAILURE() << "accepted " << e.describe();
    } catch (const std::invalid_argument& ex) {
      EXPECT_NE(std::string(ex.what()).find(part), std::string::npos) << ex.what();
    }
  };
  fails(enc(Encoding::frequency, "uv", 0, 2, 0), "encoding 'frequency' of input 'uv': bands must be 1..16, got 0");
  fails(enc(Encoding::frequency, "uv", 0, 2, 17), "bands must be 1..16, got 17");
  fails(enc(Encoding::triangle_wave, "uv", 0, 2, 40), "bands must be 1..16, got 40");
  fails(enc(Encoding::oneblob, "uv", 0, 2, 1), "bins must be 2..64, got 1");
  fails(enc(Encoding::sh, "normal", 0, 3, 5), "degree must be 1..4, got 5");
  fails(enc(Encoding::sh, "normal", 0, 3, 0), "degree must be 1..4, got 0");
  fails(enc(Encoding::sh, "uv", 0, 2), "encoding 'sh' of input 'uv': needs an input of 3 components");
  fails(enc(Encoding::oneblob, "position", 0, 3), "'position' has no fixed range; give it as range = {min, max}");
  InputEncoding backwards = enc(Encoding::oneblob, "uv", 0, 2);
  backwards.lo = 1, backwards.hi = 0;
  fails(backwards, "range must be two finite numbers {min, max} with min < max, got {1, 0}");
  // A registered name cannot be taken again by a definition.
  EncodingDef d;
  d.name = "sh";
  d.glsl = "return 0.0;";
  d.out_width = [](int w, int, bool) { return w; };
  d.f = [](const InputEncoding&, const double*, int) { return 0.0; };
  EXPECT_THROW(register_encoding(d), std::invalid_argument);
}

// The built-ins pass the checks a user's definition must (nn/encoding_define.h): their GLSL
// agrees with their twins at every width and count, on inputs out to +-300 (frequency's and
// triangle_wave's high bands reduce exactly in float; sh's cubics keep float's relative accuracy).
TEST(EncodingRegistry, BuiltinsPassTheDefinitionChecks) {
  sn::gl::current();
  for (int id = 0; id < int(BuiltinEncoding::count); ++id) {
    SCOPED_TRACE(encoding_name(Encoding(id)));
    EXPECT_NO_THROW(check_definition(Encoding(id)));
  }
}

TEST(EncodingTwins, ValuesWorkedOutByHand) {
  // frequency, 3 bands, raw input kept, of uv = (0.3, -0.55): x, then per component sin, cos of
  // pi x, 2 pi x, 4 pi x.
  InputEncoding f = enc(Encoding::frequency, "uv", 0, 2, 3);
  ASSERT_TRUE(f.include_input);
  ASSERT_EQ(f.out_width(), 2 + 2 * 3 * 2);
  const double uv[2] = {0.3, -0.55};
  std::vector<double> out(16);  // the widest below: sh 4 and oneblob 8 of uv
  encode_row({f}, 2, uv, out.data());
  std::vector<double> want = {0.3, -0.55};
  for (double x : uv)
    for (int k = 0; k < 3; ++k) want.push_back(std::sin(kPi * x * (1 << k))), want.push_back(std::cos(kPi * x * (1 << k)));
  for (int j = 0; j < 14; ++j) EXPECT_NEAR(out[j], want[j], 1e-15) << j;

  // triangle_wave, 3 bands, without the raw input: 4 |frac(2^(k-1) x + k/4) - 1/2| - 1.
  InputEncoding t = enc(Encoding::triangle_wave, "uv", 0, 2, 3);
  ASSERT_FALSE(t.include_input);
  encode_row({t}, 2, uv, out.data());
  // x = 0.3: 0.15 -> 4|0.15-0.5|-1 = 0.4; 0.3+0.25 = 0.55 -> -0.8; 0.6+0.5 = 1.1 -> 0.6.
  const double tri[6] = {0.4, -0.8, 0.6, -0.1, -0.2, -0.6};
  for (int j = 0; j < 6; ++j) EXPECT_NEAR(out[j], tri[j], 1e-12) << j;

  // sh, degree 4, of (x, y, z) = (0.48, 0.6, 0.64): the tiny-cuda-nn polynomials.
  const double v[3] = {0.48, 0.6, 0.64};
  encode_row({enc(Encoding::sh, "normal", 0, 3, 4)}, 3, v, out.data());
  const double x = v[0], y = v[1], z = v[2];
  const double c0 = 0.5 / std::sqrt(kPi), c1 = std::sqrt(3.0) * c0;
  EXPECT_NEAR(out[0], c0, 1e-15);
  EXPECT_NEAR(out[1], -c1 * y, 1e-15);
  EXPECT_NEAR(out[2], c1 * z, 1e-15);
  EXPECT_NEAR(out[3], -c1 * x, 1e-15);
  EXPECT_NEAR(out[6], std::sqrt(5.0) * (3 * z * z - 1) / (4 * std::sqrt(kPi)), 1e-14);
  EXPECT_NEAR(out[12], std::sqrt(7.0) * z * (5 * z * z - 3) / (4 * std::sqrt(kPi)), 1e-14);
  EXPECT_NEAR(out[15], std::sqrt(70.0) * x * (-x * x + 3 * y * y) / (8 * std::sqrt(kPi)), 1e-14);
  // Orthonormal on the sphere: a Monte-Carlo-free check, the integral of Y_j Y_k over a fine
  // latitude-longitude grid.
  double gram[16][16] = {};
  const int N = 200;
  for (int a = 0; a < N; ++a)
    for (int b = 0; b < 2 * N; ++b) {
      const double th = (a + 0.5) * kPi / N, ph = (b + 0.5) * kPi / N;
      const double d[3] = {std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)};
      double s[16];
      encode_row({enc(Encoding::sh, "normal", 0, 3, 4)}, 3, d, s);
      const double dw = std::sin(th) * (kPi / N) * (kPi / N);
      for (int j = 0; j < 16; ++j)
        for (int k = 0; k < 16; ++k) gram[j][k] += s[j] * s[k] * dw;
    }
  for (int j = 0; j < 16; ++j)
    for (int k = 0; k < 16; ++k) EXPECT_NEAR(gram[j][k], j == k ? 1.0 : 0.0, 2e-4) << j << " " << k;

  // oneblob, 8 bins on [0, 1], of 0.5: symmetric around the middle, its mass almost all inside.
  encode_row({enc(Encoding::oneblob, "uv", 0, 2, 8)}, 2, std::vector<double>{0.5, 0.0}.data(), out.data());
  double mass = 0;
  for (int i = 0; i < 8; ++i) mass += out[i];
  EXPECT_NEAR(mass, 1.0, 1e-4);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(out[i], out[7 - i], 1e-14);
  EXPECT_NEAR(out[3], 0.5 * std::erf(1 / std::sqrt(2.0)), 1e-15);  // Phi(1) - Phi(0): bins 4 and 5 share its peak
  // uv.y = 0 at the edge: half the mass falls off.
  mass = 0;
  for (int i = 8; i < 16; ++i) mass += out[i];
  EXPECT_NEAR(mass, 0.5, 1e-9);
}

class EncodingCase : public ::testing::TestWithParam<Case> {};
INSTANTIATE_TEST_SUITE_P(Encodings, EncodingCase, ::testing::ValuesIn(cases()),
                         [](const auto& info) { return std::string(info.param.name); });

// What every gl path runs (mlp_encode, shaders/include/mlp/encoding.glsl) against the twins, at
// uniform random points and at the edges of the ranges (uv 0 and 1, the poles).
TEST_P(EncodingCase, GlslMatchesTheTwins) {
  sn::gl::current();
  MlpSpec s = spec_with(GetParam().encodings);
  s.validate();
  Dataset d = rows_of(500, 1, 3);
  std::vector<float> x = d.train_x;
  const float edges[][8] = {{0, 0, 1, 0, 0, -1, 0, 1}, {1, 0, 0, 0, 1, 0, 1, 0}, {0.6f, 0, 0.8f, 0, -0.6f, 0.8f, 0.5f, 1}};
  for (const auto& e : edges) x.insert(x.end(), e, e + 8);
  const std::size_t rows = x.size() / 8, w = std::size_t(s.width(0));
  const std::vector<float> got = gl_encode(s, x);
  std::vector<double> want(rows * w);
  for (std::size_t r = 0; r < rows; ++r) {
    double xd[8];
    for (int i = 0; i < 8; ++i) xd[i] = x[r * 8 + i];
    encode_row(s.encodings, 8, xd, &want[r * w]);
  }
  EXPECT_LE(max_diff(got, want), 2e-6) << s.describe();
  // The row twins (f_row, where an encoding has one) give exactly the per-output twins' values.
  for (std::size_t r = 0; r < rows; ++r) {
    std::size_t o = 0;
    double xd[8];
    for (int i = 0; i < 8; ++i) xd[i] = x[r * 8 + i];
    for (int i = 0; i < 8;) {
      const InputEncoding* g = nullptr;
      for (const auto& e : s.encodings)
        if (e.offset == i) g = &e;
      if (!g) {
        EXPECT_EQ(want[r * w + o++], xd[i++]);
        continue;
      }
      for (int j = 0; j < g->out_width(); ++j) EXPECT_EQ(want[r * w + o++], encoding_def(g->kind).f(*g, xd + i, j)) << j;
      i += g->width;
    }
  }
  // And the float rows the cpu backend trains on.
  EXPECT_LE(max_diff(encode_rows(s.encodings, 8, x.data(), rows), want), 1e-7);
}

TEST_P(EncodingCase, ForwardMatchesOracleOnBothBackends) {
  sn::gl::current();
  const MlpSpec s = spec_with(GetParam().encodings, {12, 9});
  Mlp net(s, Init::xavier, 11);
  for (std::size_t j = 0; j < net.params.size(); ++j) net.params[j] += float(0.2 * (uniform01(4, j) - 0.5));
  const Dataset d = rows_of(203, 1, 5);
  const std::size_t n = d.train_count();
  const std::vector<double> pd(net.params.begin(), net.params.end());
  std::vector<double> want(n * 3);
  for (std::size_t r = 0; r < n; ++r) {
    double x[8];
    for (int i = 0; i < 8; ++i) x[i] = d.train_x[r * 8 + i];
    const auto y = oracle::forward(s, pd, x);
    for (int o = 0; o < 3; ++o) want[r * 3 + o] = y[std::size_t(o)];
  }
  EXPECT_LE(max_diff(gl_forward(net, d.train_x), want), 1e-5) << "gl " << s.describe();
  CpuNet cpu(s, net.params.data());
  std::vector<float> out(n * 3);
  const std::vector<float> enc_rows = encode_rows(s.encodings, 8, d.train_x.data(), n);
  cpu.forward(enc_rows.data(), n, out.data());
  EXPECT_LE(max_diff(out, want), 1e-5) << "cpu " << s.describe();
  // The oracle's first layer reads the twins' encoding: an identity network fed pre-encoded
  // rows computes the same.
  MlpSpec plain = s;
  plain.encodings.clear();
  plain.inputs = s.width(0);
  double worst = 0;
  for (std::size_t r = 0; r < n; ++r) {
    double x[8];
    for (int i = 0; i < 8; ++i) x[i] = d.train_x[r * 8 + i];
    std::vector<double> e(std::size_t(s.width(0)));
    encode_row(s.encodings, 8, x, e.data());
    const auto y = oracle::forward(plain, pd, e.data());
    for (int o = 0; o < 3; ++o) worst = std::max(worst, std::fabs(y[std::size_t(o)] - want[r * 3 + o]));
  }
  EXPECT_EQ(worst, 0.0);
}

// One Adam step (8 rows, batch 8) against the oracle, on the cpu backend and both gl kernels.
TEST_P(EncodingCase, OneAdamStepMatchesOracleOnBothBackends) {
  sn::gl::current();
  // Small enough for the per-network kernel (at most 128 padded parameter vec4s).
  const MlpSpec s = spec_with(GetParam().encodings, {6, 5});
  Mlp net(s, Init::xavier, 7);
  const Dataset d = rows_of(8, 16, 9);
  TrainConfig cfg;
  cfg.epochs = 1;
  cfg.batch = 8;
  cfg.lr = 1e-2;
  const NetResult o = oracle::train(s, net.params, d, cfg);
  auto check = [&](const std::vector<NetResult>& r, const std::string& who) {
    ASSERT_EQ(r.size(), 1u) << who;
    EXPECT_EQ(r[0].steps, 1) << who;
    double worst = 0, moved = 0;
    for (std::size_t j = 0; j < net.params.size(); ++j) {
      worst = std::max(worst, std::fabs(double(r[0].final_params[j]) - double(o.final_params[j])));
      moved = std::max(moved, std::fabs(double(r[0].final_params[j]) - double(net.params[j])));
    }
    EXPECT_LE(worst, 1e-5) << who << " " << s.describe();
    EXPECT_GT(moved, 5e-3) << who << ": the step changed nothing";
    EXPECT_NEAR(r[0].val_mse[0], o.val_mse[0], 1e-5 * o.val_mse[0]) << who;
  };
  check(make_cpu_backend(1)->train({&net}, d, cfg, nullptr), "cpu");
  for (auto k : {GlTrainOptions::Kernel::per_sample, GlTrainOptions::Kernel::per_net}) {
    GlTrainOptions opt;
    opt.kernel = k;
    GlTrainer gl(opt);
    check(gl.train({&net}, d, cfg, nullptr), k == GlTrainOptions::Kernel::per_net ? "gl per_net" : "gl per_sample");
  }
}

TEST(EncodingSpec, WidthDescriptionGroupingAndValidation) {
  MlpSpec s = spec_with({enc(Encoding::sh, "normal", 0, 3, 4), enc(Encoding::frequency, "uv", 6, 2, 8)}, {32, 32});
  s.activation = Activation::relu;
  s.validate();
  EXPECT_EQ(s.width(0), 16 + 3 + 2 + 32);
  EXPECT_EQ(s.weight_offset(1), std::size_t(53 + 1) * 32);
  EXPECT_EQ(s.describe(), "mlp(8 -> 32x2 -> 3, relu; normal: sh 4, uv: frequency 8 -> 53 inputs)");
  MlpSpec t = s;
  t.encodings[1].include_input = false;
  EXPECT_EQ(t.describe(), "mlp(8 -> 32x2 -> 3, relu; normal: sh 4, uv: frequency 8 - input -> 51 inputs)");
  EXPECT_FALSE(s.same_shape(t));  // another encoding is another group of the gl trainer
  EXPECT_TRUE(s.same_shape(MlpSpec(s)));
  MlpSpec plain = s;
  plain.encodings.clear();
  EXPECT_FALSE(s.same_shape(plain));
  // Overlapping groups, a group past the inputs, too wide an encoded input.
  MlpSpec bad = s;
  bad.encodings[1].offset = 2;
  EXPECT_THROW(bad.validate(), std::invalid_argument);
  bad = s;
  bad.encodings[1].offset = 7;
  EXPECT_THROW(bad.validate(), std::invalid_argument);
  bad = spec_with({enc(Encoding::oneblob, "normal", 0, 3, 64), enc(Encoding::oneblob, "view", 3, 3, 64)});
  try {
    bad.validate();
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "the encoded inputs are 386 wide, at most 256 (fewer bands, bins or a lower degree)");
  }
}

// The cpu trainer encodes a dataset once per distinct set of encodings: networks with different
// encodings in one job each train as they would alone.
TEST(EncodingCpu, MixedEncodingsInOneJobTrainAsAlone) {
  const Dataset d = rows_of(64, 16, 2);
  TrainConfig cfg;
  cfg.epochs = 2;
  cfg.batch = 8;
  cfg.lr = 3e-3;
  std::vector<Mlp> nets = {Mlp(spec_with({}), Init::xavier, 1),
                           Mlp(spec_with({enc(Encoding::frequency, "uv", 6, 2, 4)}), Init::xavier, 2),
                           Mlp(spec_with({enc(Encoding::sh, "normal", 0, 3, 3)}), Init::xavier, 3),
                           Mlp(spec_with({enc(Encoding::frequency, "uv", 6, 2, 4)}), Init::xavier, 4)};
  auto together = make_cpu_backend(2)->train({&nets[0], &nets[1], &nets[2], &nets[3]}, d, cfg, nullptr);
  for (std::size_t i = 0; i < nets.size(); ++i) {
    auto alone = make_cpu_backend(1)->train({&nets[i]}, d, cfg, nullptr);
    EXPECT_EQ(alone[0].final_params, together[i].final_params) << i;
    EXPECT_EQ(alone[0].val_mse, together[i].val_mse) << i;
  }
}

}  // namespace sn::nn

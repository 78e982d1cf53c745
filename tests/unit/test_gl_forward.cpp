// The compute-shader forward pass (shaders/mlp_eval.comp via nn/gl_forward.h) against the
// double-precision oracle.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "gl/context.h"
#include "gl/program.h"
#include "nn/gl_forward.h"
#include "nn/mlp.h"
#include "nn/mlp_shader.h"
#include "nn/oracle.h"

using namespace sn::nn;

namespace {

MlpSpec make_spec(int in, std::vector<int> hidden, int out, Activation act, Activation out_act = Activation::linear,
                  double slope = 0.01) {
  MlpSpec s;
  s.inputs = in;
  s.hidden = std::move(hidden);
  s.outputs = out;
  s.activation = act;
  s.output_activation = out_act;
  s.slope = slope;
  return s;
}

std::vector<float> random_rows(std::size_t rows, int width, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-1.f, 1.f);
  std::vector<float> x(rows * std::size_t(width));
  for (float& v : x) v = u(rng);
  return x;
}

// Largest |gl - oracle| over every output of every row.
double max_error(const Mlp& net, const std::vector<float>& x, const std::vector<float>& y) {
  std::vector<double> p(net.params.begin(), net.params.end());
  const std::size_t rows = x.size() / std::size_t(net.spec.inputs);
  double worst = 0;
  std::vector<double> xi(std::size_t(net.spec.inputs));
  for (std::size_t r = 0; r < rows; ++r) {
    for (int i = 0; i < net.spec.inputs; ++i) xi[std::size_t(i)] = x[r * std::size_t(net.spec.inputs) + std::size_t(i)];
    auto want = oracle::forward(net.spec, p, xi.data());
    for (int o = 0; o < net.spec.outputs; ++o)
      worst = std::max(worst, std::abs(double(y[r * std::size_t(net.spec.outputs) + std::size_t(o)]) - want[std::size_t(o)]));
  }
  return worst;
}

}  // namespace

struct ForwardCase {
  const char* name;
  MlpSpec spec;
};
void PrintTo(const ForwardCase& c, std::ostream* os) { *os << c.name; }  // test names, not bytes

class GlForward : public ::testing::TestWithParam<ForwardCase> {};

TEST_P(GlForward, MatchesOracleWithin1e5) {
  sn::gl::current();
  const MlpSpec& spec = GetParam().spec;
  Mlp net(spec, Init::xavier, 42);
  // Rows not a multiple of the workgroup size: the tail must be evaluated too.
  auto x = random_rows(1000 + 37, spec.inputs, 3);
  auto y = gl_forward(net, x);
  ASSERT_EQ(y.size(), 1037u * std::size_t(spec.outputs));
  double err = max_error(net, x, y);
  EXPECT_LE(err, 1e-5) << spec.describe();
  // A forward pass that did nothing would leave zeros: the outputs must carry signal.
  double energy = 0;
  for (float v : y) energy += std::abs(v);
  EXPECT_GT(energy, 1e-3 * double(y.size())) << spec.describe();
}

INSTANTIATE_TEST_SUITE_P(
    Architectures, GlForward,
    ::testing::Values(ForwardCase{"tanh_4x6", make_spec(6, {6, 6, 6, 6}, 3, Activation::tanh)},
                      ForwardCase{"tanh_12x12", make_spec(6, std::vector<int>(12, 12), 3, Activation::tanh)},
                      ForwardCase{"sigmoid_out_sigmoid", make_spec(5, {7, 3}, 2, Activation::sigmoid, Activation::sigmoid)},
                      ForwardCase{"relu", make_spec(6, {9, 9, 9}, 3, Activation::relu)},
                      ForwardCase{"leaky_relu", make_spec(6, {8, 8}, 3, Activation::leaky_relu, Activation::linear, 0.2)},
                      ForwardCase{"wide_loops_not_unrolled", make_spec(6, {40, 33, 40}, 4, Activation::tanh, Activation::tanh)},
                      ForwardCase{"thesis_13_to_6", make_spec(6, {13, 13, 13, 13, 6, 6, 6, 6}, 3, Activation::tanh)},
                      ForwardCase{"sine", make_spec(6, {8, 8}, 3, Activation::sine, Activation::sine)},
                      ForwardCase{"softplus", make_spec(6, {8, 8}, 3, Activation::softplus, Activation::softplus)},
                      ForwardCase{"squareplus", make_spec(6, {8, 8}, 3, Activation::squareplus)},
                      ForwardCase{"elu", make_spec(6, {8, 8}, 3, Activation::elu, Activation::elu)},
                      ForwardCase{"gelu", make_spec(6, {8, 8}, 3, Activation::gelu, Activation::gelu)},
                      ForwardCase{"swish", make_spec(6, {8, 8}, 3, Activation::swish, Activation::swish)},
                      ForwardCase{"exponential", make_spec(6, {8}, 3, Activation::exponential)}),
    [](const ::testing::TestParamInfo<ForwardCase>& i) { return std::string(i.param.name); });

TEST(GlForwardLoss, SquaredErrorsOfManyNetsInOneDispatch) {
  sn::gl::current();
  MlpSpec spec = make_spec(6, {8, 8, 8}, 3, Activation::tanh);
  const std::size_t PQ = padded_chunks(spec), rows = 700, nets = 5, stride = PQ + 3;  // a gap between nets
  std::vector<float> all(4 * stride * nets, 0.f);
  std::vector<Mlp> mlps;
  for (std::size_t n = 0; n < nets; ++n) {
    mlps.emplace_back(spec, Init::xavier, 100 + n);
    pack_padded(spec, mlps.back().params.data(), all.data() + 4 * n * stride);
  }
  auto x = random_rows(rows, 6, 5), y = random_rows(rows, 3, 6);
  sn::gl::Buffer pb(sn::gl::ElemType::vec4, all.size() / 4), xb(sn::gl::ElemType::float32, x.size()),
      yb(sn::gl::ElemType::float32, y.size());
  pb.upload(all.data(), 0, all.size());
  xb.upload(x.data(), 0, x.size());
  yb.upload(y.data(), 0, y.size());
  auto sums = gl_squared_errors(spec, GlParams{&pb, 0, stride, int(nets)}, xb, yb, rows);
  ASSERT_EQ(sums.size(), nets);
  for (std::size_t n = 0; n < nets; ++n) {
    std::vector<double> p(mlps[n].params.begin(), mlps[n].params.end());
    double want = oracle::mse(spec, p, x.data(), y.data(), rows) * double(rows) * 3;
    EXPECT_NEAR(sums[n], want, 1e-5 * want) << "net " << n;
  }
  // Different nets give different errors (each workgroup row read its own parameters).
  EXPECT_NE(sums[0], sums[1]);
}

TEST(GlForwardLoss, OutputsOfManyNetsLandInTheirOwnRows) {
  sn::gl::current();
  MlpSpec spec = make_spec(3, {5, 5}, 2, Activation::tanh);
  const std::size_t PQ = padded_chunks(spec), rows = 130;
  Mlp a(spec, Init::xavier, 1), b(spec, Init::xavier, 2);
  std::vector<float> all = pack_padded(spec, a.params.data()), pb2 = pack_padded(spec, b.params.data());
  all.insert(all.end(), pb2.begin(), pb2.end());
  auto x = random_rows(rows, 3, 9);
  sn::gl::Buffer pb(sn::gl::ElemType::vec4, all.size() / 4), xb(sn::gl::ElemType::float32, x.size()),
      out(sn::gl::ElemType::float32, 2 * rows * 2);
  pb.upload(all.data(), 0, all.size());
  xb.upload(x.data(), 0, x.size());
  gl_forward(spec, GlParams{&pb, 0, PQ, 2}, xb, rows, out);
  auto y = out.download_floats();
  std::vector<float> ya(y.begin(), y.begin() + long(rows * 2)), yb(y.begin() + long(rows * 2), y.end());
  EXPECT_LE(max_error(a, x, ya), 1e-5);
  EXPECT_LE(max_error(b, x, yb), 1e-5);
}

// The largest network the spec allows (32 hidden layers of 64): its wide layers' loops stay
// rolled (compile time) and still fit llvmpipe's loop budget per row.
TEST(GlForwardLoss, LargestArchitectureMatchesOracle) {
  sn::gl::current();
  Mlp net(make_spec(64, std::vector<int>(32, 64), 64, Activation::tanh), Init::xavier, 1);
  auto x = random_rows(19, 64, 1);
  auto y = gl_forward(net, x);
  EXPECT_LE(max_error(net, x, y), 1e-5);
}

TEST(GlForwardLoss, PaddedLayoutRoundTrips) {
  MlpSpec spec = make_spec(5, {7, 3}, 2, Activation::tanh);
  Mlp net(spec, Init::xavier, 3);
  auto padded = pack_padded(spec, net.params.data());
  // Rows of 5 inputs take 2 vec4s, 7 outputs take 2 bias vec4s: (7*2 + 2) + (3*2 + 1) + (2*1 + 1).
  EXPECT_EQ(padded_chunks(spec), 26u);
  EXPECT_EQ(padded[4 * 2 + 0], net.params[5]);  // row 1 starts at vec4 2
  EXPECT_EQ(padded[5], 0.f);                    // padding after row 0's 5 weights
  std::vector<float> back(spec.param_count(), -1.f);
  unpack_padded(spec, padded.data(), back.data());
  EXPECT_EQ(back, net.params);
}

TEST(GlForwardLoss, ShapeErrorsAreClear) {
  sn::gl::current();
  Mlp net(make_spec(6, {4}, 3, Activation::tanh), Init::xavier, 1);
  try {
    gl_forward(net, std::vector<float>(13, 0.f));
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("not whole rows of 6 inputs"), std::string::npos) << e.what();
  }
}

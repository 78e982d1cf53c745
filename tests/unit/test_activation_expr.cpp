// A user's activation GLSL translated for the cpu backend (nn/activation_expr.h) and run by every
// kernel this CPU has (nn/cpu_expr.h): each translated GLSL function against its double-precision
// definition, every built-in's own GLSL against its twins (the registry's shipped definitions
// exercise the statement forms, bvec mixes and project functions), the registers a long
// expression needs, and the errors for what does not translate.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "nn/activation.h"
#include "nn/activation_expr.h"
#include "nn/cpu_net.h"

namespace sn::nn {
namespace {

// `glsl` translated and run on z by the kernel `k`, p = `param`.
std::vector<float> run(const std::string& glsl, const std::vector<float>& z, float param = 0.0f) {
  const ActivationExpr e = translate_activation(glsl);
  std::vector<float> out(z.size());
  cpu_translated(e, param, z.data(), z.size(), out.data());
  return out;
}

std::vector<float> grid(double from, double to, int n) {
  std::vector<float> z;
  for (int i = 0; i <= n; ++i) z.push_back(float(from + (to - from) * i / n));
  return z;
}

std::string error_of(const std::string& glsl) {
  try {
    translate_activation(glsl);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(translated)";
}

// Worst error of `glsl` on z against want(z) in double, relative to max(1, |want|).
double worst(const std::string& glsl, const std::vector<float>& z, const std::function<double(double)>& want) {
  const std::vector<float> got = run(glsl, z);
  double w = 0;
  for (std::size_t i = 0; i < z.size(); ++i) {
    const double y = want(double(z[i]));
    w = std::max(w, std::fabs(double(got[i]) - y) / std::max(1.0, std::fabs(y)));
  }
  return w;
}

struct Case {
  const char* glsl;
  std::function<double(double)> want;
  double from, to, tolerance;
};

TEST(ActivationExpr, EveryFunctionMatchesItsDefinitionOnEveryKernel) {
  const double pi = 3.14159265358979323846;
  const std::vector<Case> cases = {
      {"abs(x)", [](double x) { return std::fabs(x); }, -9, 9, 0},
      {"floor(x)", [](double x) { return std::floor(x); }, -9.7, 9.7, 0},
      {"ceil(x)", [](double x) { return std::ceil(x); }, -9.7, 9.7, 0},
      {"fract(x)", [](double x) { return x - std::floor(x); }, -9.7, 9.7, 1e-6},
      {"mod(x, 2.0)", [](double x) { return x - 2 * std::floor(x / 2); }, -9.7, 9.7, 1e-6},
      {"sign(x)", [](double x) { return double((x > 0) - (x < 0)); }, -3, 3, 0},
      {"step(0.25, x)", [](double x) { return x < 0.25 ? 0.0 : 1.0; }, -3, 3, 0},
      {"smoothstep(-1.0, 2.0, x)",
       [](double x) {
         const double t = std::clamp((x + 1) / 3, 0.0, 1.0);
         return t * t * (3 - 2 * t);
       },
       -3, 3, 1e-6},
      {"clamp(x, -0.5, 0.75)", [](double x) { return std::clamp(x, -0.5, 0.75); }, -3, 3, 0},
      {"min(x, 0.5) + max(x, -0.5)", [](double x) { return std::min(x, 0.5) + std::max(x, -0.5); }, -3, 3, 1e-7},
      {"mix(x, x * x, 0.25)", [](double x) { return 0.75 * x + 0.25 * x * x; }, -3, 3, 1e-6},
      {"exp(x)", [](double x) { return std::exp(x); }, -80, 80, 1e-6},
      {"exp2(x)", [](double x) { return std::exp2(x); }, -30, 30, 3e-6},
      {"log(x)", [](double x) { return std::log(x); }, 1e-30, 1e30, 1e-6},
      {"log(x)", [](double x) { return std::log(x); }, 0.5, 2, 1e-7},
      {"log2(x)", [](double x) { return std::log2(x); }, 1e-3, 1e3, 1e-6},
      {"pow(x, 1.7)", [](double x) { return std::pow(x, 1.7); }, 1e-3, 50, 2e-6},
      {"sqrt(x)", [](double x) { return std::sqrt(x); }, 0, 100, 1e-7},
      {"inversesqrt(x)", [](double x) { return 1 / std::sqrt(x); }, 1e-2, 100, 1e-6},
      {"sin(x) + cos(x)", [](double x) { return std::sin(x) + std::cos(x); }, -50, 50, 1e-6},
      {"tan(x)", [](double x) { return std::tan(x); }, -1.4, 1.4, 1e-6},
      {"asin(x) + acos(x) * 0.5", [](double x) { return std::asin(x) + 0.5 * std::acos(x); }, -1, 1, 1e-6},
      {"atan(x)", [](double x) { return std::atan(x); }, -1e4, 1e4, 1e-6},
      {"atan(x)", [](double x) { return std::atan(x); }, -3, 3, 1e-6},
      {"sinh(x)", [](double x) { return std::sinh(x); }, -10, 10, 1e-6},
      {"cosh(x)", [](double x) { return std::cosh(x); }, -10, 10, 1e-6},
      {"tanh(x)", [](double x) { return std::tanh(x); }, -20, 20, 2e-6},
      {"asinh(x)", [](double x) { return std::asinh(x); }, -100, 100, 1e-6},
      {"acosh(x)", [](double x) { return std::acosh(x); }, 1, 100, 1e-6},
      {"atanh(x)", [](double x) { return std::atanh(x); }, -0.99, 0.99, 1e-6},
      {"radians(degrees(x))", [](double x) { return x; }, -9, 9, 1e-6},
      {"sn_gelu_tanh(x)", [](double x) { return std::tanh(0.7978845608028654 * (x + 0.044715 * x * x * x)); }, -12, 12, 2e-6},
      // statements, compound assignment, comments, the ternary and the logic operators
      {"float a = 2.0; // a comment\n vec4 y = x; y *= a; y += 1.0; /* another */ return y - 0.5;",
       [](double x) { return 2 * x + 0.5; }, -3, 3, 1e-7},
      {"return (x > 0.5 && x < 1.5) || !(x > -1.0) ? x : -x;",
       [](double x) { return (x > 0.5 && x < 1.5) || !(x > -1.0) ? x : -x; }, -3, 3, 0},
      {"mix(x, vec4(2.0), lessThanEqual(x, vec4(0.0)))", [](double x) { return x <= 0 ? 2.0 : x; }, -3, 3, 0},
  };
  const std::string saved = cpu_kernel_name();
  for (const auto& k : cpu_kernels_available()) {
    use_cpu_kernel(k);
    for (const Case& c : cases) {
      const std::vector<float> z = std::string(c.glsl) == "log(x)" && c.to > 1e3
                                       ? [] {
                                           std::vector<float> v;
                                           for (double e = -30; e <= 30; e += 0.001) v.push_back(float(std::pow(10.0, e)));
                                           return v;
                                         }()
                                       : grid(c.from, c.to, 20011);
      EXPECT_LE(worst(c.glsl, z, c.want), c.tolerance) << c.glsl << " on [" << c.from << ", " << c.to << "], kernel " << k;
    }
    // Special values as the built-ins' elementary functions give them.
    const float inf = INFINITY;
    const std::vector<float> special = {0.0f, -1.0f, inf, -inf, NAN};
    const std::vector<float> lg = run("log(x)", special), ex = run("exp(x)", special), at = run("atan(x)", special);
    EXPECT_EQ(lg[0], -inf) << k;
    EXPECT_TRUE(std::isnan(lg[1]) && lg[2] == inf && std::isnan(lg[3]) && std::isnan(lg[4])) << k;
    EXPECT_TRUE(ex[2] == inf && ex[3] >= 0.0f && ex[3] < 1.2e-38f && std::isnan(ex[4])) << k;
    EXPECT_NEAR(at[2], pi / 2, 1e-7) << k;
    EXPECT_NEAR(at[3], -pi / 2, 1e-7) << k;
    EXPECT_TRUE(std::isnan(at[4])) << k;
    EXPECT_TRUE(std::isnan(run("x / (1.0 + abs(x))", {NAN})[0])) << k << ": NaN must not turn into a number";
    EXPECT_FLOAT_EQ(run("p * x", {2.0f}, 1.5f)[0], 3.0f) << k;
    EXPECT_EQ(run("mix(-x, x, not(equal(x, vec4(1.0))))", {1.0f, 2.0f}), (std::vector<float>{-1.0f, 2.0f})) << k;
  }
  use_cpu_kernel(saved);
}

// The shipped activations' own GLSL through the translator: the same registry entries the gl
// backend compiles, held to the double twins.
TEST(ActivationExpr, TheBuiltInsOwnGlslMatchesTheirTwins) {
  const std::string saved = cpu_kernel_name();
  const std::vector<float> z = grid(-20, 20, 40013);
  for (const auto& k : cpu_kernels_available()) {
    use_cpu_kernel(k);
    for (int id = 0; id < int(Builtin::count); ++id) {
      const ActivationDef& d = activation_def(Activation(id));
      const double p = d.param == ActivationParam::none ? 0.0 : 0.7;
      for (bool grad : {false, true}) {
        const std::vector<float> got = run(grad ? d.grad : d.glsl, z, float(p));
        double w = 0;
        for (std::size_t i = 0; i < z.size(); ++i) {
          const double want = grad ? d.df(z[i], p) : d.f(z[i], p);
          w = std::max(w, std::fabs(got[i] - want) / std::max(1.0, std::fabs(want)));
        }
        EXPECT_LE(w, grad ? 5e-6 : 2e-6) << d.name << (grad ? " grad" : " glsl") << ", kernel " << k;
      }
    }
  }
  use_cpu_kernel(saved);
}

// f and f' in one program: what they share runs once, and each comes out as alone.
TEST(ActivationExpr, TheDerivativeSharesTheFunctionsSteps) {
  const std::string f = "1.0 / (1.0 + exp(-x))", g = "vec4 s = 1.0 / (1.0 + exp(-x)); return s * (1.0 - s);";
  const ActivationExpr alone_f = translate_activation(f), alone_g = translate_activation(g), both = translate_activation(f, g);
  auto count = [](const ActivationExpr& e, ExprOp op) {
    int n = 0;
    for (const ExprStep& s : e.steps) n += s.op == op;
    return n;
  };
  EXPECT_EQ(count(both, ExprOp::exp), 1);
  EXPECT_EQ(both.steps.size(), alone_g.steps.size());  // f' computes f on the way: f costs nothing more
  const std::vector<float> z = grid(-30, 30, 6007);
  std::vector<float> a(z.size()), b(z.size()), bf(z.size()), bg(z.size());
  cpu_translated(alone_f, 0.0f, z.data(), z.size(), a.data());
  cpu_translated(alone_g, 0.0f, z.data(), z.size(), b.data());
  cpu_translated(both, 0.0f, z.data(), z.size(), bf.data(), bg.data());
  EXPECT_EQ(a, bf);
  EXPECT_EQ(b, bg);
}

TEST(ActivationExpr, RegistersAreReusedAndBounded) {
  // 200 terms, each read once: the allocation frees each as it is added.
  std::string sum = "x";
  for (int i = 1; i <= 200; ++i) sum += " + " + std::to_string(i) + ".0 * x * x";
  const ActivationExpr e = translate_activation(sum);
  EXPECT_LE(e.registers, 5);
  EXPECT_NEAR(run(sum, {0.5f})[0], 0.5 + 20100 * 0.25, 1e-3);
  // Nesting keeps every left operand alive until its right one is made.
  std::string deep = "x";
  for (int i = 0; i < 60; ++i) deep = "(x * " + std::to_string(i) + ".5 + " + deep + " * x)";
  EXPECT_NE(error_of(deep).find("values live at once, the most the cpu backend holds"), std::string::npos) << error_of(deep);
}

TEST(ActivationExpr, WhatDoesNotTranslateIsNamedWithItsLine) {
  EXPECT_EQ(error_of("vec4 s = x;\nreturn x.x * s;"), "line 2: '.' (a swizzle or a member) is not translated for the cpu backend");
  const std::string atan2 = error_of("atan(x, vec4(1.0))");
  EXPECT_EQ(atan2, "line 1: atan takes 1 argument");
  const std::string fn = error_of("x +\n erf(x)");
  EXPECT_EQ(fn.rfind("line 2: 'erf' is not translated for the cpu backend, which translates abs, acos,", 0), 0u) << fn;
  const std::string loop = error_of("vec4 s = x; for (int i = 0; i < 2; i++) s = sin(s); return s;");
  EXPECT_EQ(loop.rfind("line 1: 'for' is not translated for the cpu backend, which translates declarations", 0), 0u) << loop;
  EXPECT_EQ(error_of("vec4 s = x; s = s * 2.0; // no return"), "line 1: no return");
  EXPECT_EQ(error_of("lessThan(x, vec4(0.0))"), "line 1: the result is a bvec, not a number");
  EXPECT_EQ(error_of("vec4(x, x, 1.0, x)"), "line 1: vec4 of 4 values: the cpu backend translates componentwise code only");
  EXPECT_EQ(error_of("y * 2.0"), "line 1: 'y' is not a name the cpu backend knows (z, x, p or a local)");
  EXPECT_EQ(error_of("x # 2.0"), "line 1: '#' is not translated for the cpu backend");
  EXPECT_EQ(error_of("x /* open"), "line 1: a comment that does not end");
  EXPECT_EQ(error_of(std::string(300, '(') + "x" + std::string(300, ')')), "line 1: nested more than 256 deep");
  EXPECT_EQ(error_of(std::string(100000, '-') + "x"), "line 1: nested more than 256 deep");
  std::string ternaries;
  for (int i = 0; i < 20000; ++i) ternaries += "p > 0.5 ? x : ";
  ternaries += "x";
  EXPECT_EQ(error_of(ternaries), "line 1: nested more than 256 deep");
}

}  // namespace
}  // namespace sn::nn

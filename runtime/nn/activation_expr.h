// A user's activation on the cpu backend: its GLSL (one expression, or statements ending in a
// return, over vec4 z or x and float p: nn/activation.h) translated into a short program of
// per-lane operations that the cpu kernels run on their vectors (nn/cpu_expr.h). The GLSL is
// componentwise, so each lane of a vector is one unit's sample, as in the built-ins' SIMD code.
//
// What translates: float literals; z, x, p and local names; vec4/float declarations,
// assignments (= += -= *= /=) and return; + - * / (unary too), comparisons, !, &&, ||, ?: and
// the GLSL functions named by expr_functions(). Anything else (if, loops, swizzles, user
// functions) is an error naming it; such a definition then runs on the gl backend only.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace sn::nn {

enum class ExprOp : uint8_t {
  constant,  // k
  add, sub, mul, div, min, max,
  neg, abs, floor, sqrt, exp, log, sin, cos, tanh, atan,
  less, less_equal, equal, not_equal,  // masks: 1 where true, 0 where not
  select,  // a ? b : c, lane by lane (a a mask)
};

// One operation: registers dst = op(a, b, c). Register 0 holds z, register 1 p.
struct ExprStep {
  ExprOp op;
  uint8_t dst, a, b, c;
  float k;
};

struct ActivationExpr {
  std::vector<ExprStep> steps;
  int registers = 2;
  int result = 0;  // the register holding f(z)
  int grad = -1;  // the register holding f'(z), in a program translated with the derivative
};

// Most registers a program may use: the kernels keep them on the stack, a few vectors each.
constexpr int kExprRegisters = 48;

// `glsl` translated; throws std::invalid_argument naming what does not translate, and what does.
ActivationExpr translate_activation(const std::string& glsl);
// f and f' in one program (a training forward pass needs both): the steps they share run once.
ActivationExpr translate_activation(const std::string& glsl, const std::string& grad);

// The GLSL functions that translate, comma-separated (for messages and docs).
const char* expr_functions();

}  // namespace sn::nn

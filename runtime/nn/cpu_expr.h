// A user's activation translated from its GLSL (nn/activation_expr.h), run by the cpu kernels
// over a layer's vectors: each step on a few vectors at once, so that choosing the step costs
// once per few vectors, not once per vector. The elementary functions are the built-ins' own
// (nn/cpu_activation.h). Included only by nn/cpu_net.cpp, inside its kernels' targets.
#pragma once
#include <cstddef>

#include "nn/activation_expr.h"
#include "nn/cpu_activation.h"

namespace sn::nn::simd {

// A layout's activation kind for a translated definition (after the built-ins' ids).
constexpr int kTranslated = int(Builtin::count);

// out[i] = f(in[i]) for n vectors, and grad[i] = f'(in[i]) when given (a program translated with
// its derivative); out may be in.
template <class V>
SN_INLINE void run_expr(const ActivationExpr& e, float p, const V* in, std::size_t n, V* out, V* grad) {
  constexpr int kChunk = 4;
  V r[kExprRegisters][kChunk];
  for (int j = 0; j < kChunk; ++j) r[1][j] = splat<V>(p);
  const ExprStep* first = e.steps.data();
  const ExprStep* last = first + e.steps.size();
  const V zero = splat<V>(0.0f), one = splat<V>(1.0f);
  for (std::size_t base = 0; base < n; base += kChunk) {
    const std::size_t m = n - base < std::size_t(kChunk) ? n - base : std::size_t(kChunk);
    for (std::size_t j = 0; j < std::size_t(kChunk); ++j) r[0][j] = j < m ? in[base + j] : zero;
    for (const ExprStep* s = first; s != last; ++s) {
      V* d = r[s->dst];
      const V *a = r[s->a], *b = r[s->b], *c = r[s->c];
#define SN_EACH(expr) \
  for (int j = 0; j < kChunk; ++j) d[j] = (expr); \
  break
      switch (s->op) {
        case ExprOp::add: SN_EACH(a[j] + b[j]);
        case ExprOp::sub: SN_EACH(a[j] - b[j]);
        case ExprOp::mul: SN_EACH(a[j] * b[j]);
        case ExprOp::div: SN_EACH(a[j] / b[j]);
        case ExprOp::min: SN_EACH(select(b[j] < a[j], b[j], a[j]));  // GLSL's min and max
        case ExprOp::max: SN_EACH(select(a[j] < b[j], b[j], a[j]));
        case ExprOp::neg: SN_EACH(-a[j]);
        case ExprOp::abs: SN_EACH(select(a[j] < 0.0f, -a[j], a[j]));
        case ExprOp::floor: {
          // Truncated, less 1 below a negative non-integer; from 2^23 on every float is an
          // integer (and inf and NaN stay themselves).
          for (int j = 0; j < kChunk; ++j) {
            const V t = __builtin_convertvector(__builtin_convertvector(a[j], mask_of<V>), V);
            const V f = select(a[j] < t, t - 1.0f, t);
            d[j] = select(select(a[j] < 0.0f, -a[j], a[j]) < 8388608.0f, f, a[j]);
          }
          break;
        }
        case ExprOp::sqrt: SN_EACH(vsqrt<sqrt_isa<V>>(a[j]));
        case ExprOp::exp: SN_EACH(vexp(a[j]));
        case ExprOp::log: SN_EACH(vlog(a[j]));
        case ExprOp::sin:
          for (int j = 0; j < kChunk; ++j) {
            const V x = a[j];
            V unused;
            vsincos(x, d[j], unused);
          }
          break;
        case ExprOp::cos:
          for (int j = 0; j < kChunk; ++j) {
            const V x = a[j];
            V unused;
            vsincos(x, unused, d[j]);
          }
          break;
        case ExprOp::tanh: SN_EACH(fast_tanh(a[j]));
        case ExprOp::atan: SN_EACH(vatan(a[j]));
        case ExprOp::less: SN_EACH(select(a[j] < b[j], one, zero));
        case ExprOp::less_equal: SN_EACH(select(a[j] <= b[j], one, zero));
        case ExprOp::equal: SN_EACH(select(a[j] == b[j], one, zero));
        case ExprOp::not_equal: SN_EACH(select(a[j] != b[j], one, zero));
        case ExprOp::select: SN_EACH(select(a[j] != 0.0f, b[j], c[j]));
        case ExprOp::constant: SN_EACH(splat<V>(s->k));
      }
#undef SN_EACH
    }
    for (std::size_t j = 0; j < m; ++j) out[base + j] = r[e.result][j];
    if (grad)
      for (std::size_t j = 0; j < m; ++j) grad[base + j] = r[e.grad][j];
  }
}

}  // namespace sn::nn::simd

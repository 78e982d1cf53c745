// tanh as a [13/6] rational function (the minimax fit Eigen uses for float tanh), written once
// for float and for GCC vector types so the cpu kernel and its test share it. Absolute error
// against std::tanh <= 1e-6 over all floats (tests/unit/test_cpu_trainer.cpp measures it);
// NaN stays NaN (the comparisons below are false for NaN, so the clamp lets it through).
#pragma once
#if defined(__x86_64__) && !defined(__clang__)
#include <immintrin.h>  // declares the AVX-512 min and max builtins below
#endif

namespace sn::nn {

// x clamped to [-c, c] (c > 0); NaN stays NaN.
template <class T>
inline __attribute__((always_inline)) T clamp_symmetric(const T& in, float c_) {
  T x = in;
  const T c = T{} + c_;  // a splat for vector T
#if defined(__x86_64__) && !defined(__clang__)
  if constexpr (sizeof(T) == 64) {
    // 16 lanes (AVX-512 kernels): vminps and vmaxps, which pass a NaN in x through as ?: does;
    // GCC makes a compare and a blend of each ?:, and the step is 3-4% faster without them.
    x = (T)__builtin_ia32_minps512_mask((__v16sf)c, (__v16sf)x, (__v16sf)x, __mmask16(-1), _MM_FROUND_CUR_DIRECTION);
    x = (T)__builtin_ia32_maxps512_mask((__v16sf)-c, (__v16sf)x, (__v16sf)x, __mmask16(-1), _MM_FROUND_CUR_DIRECTION);
    return x;
  }
#endif
  x = x > c ? c : x;
  x = x < -c ? -c : x;
  return x;
}

template <class T>
inline __attribute__((always_inline)) T fast_tanh(const T& in) {
  // Clamping keeps the polynomials in range, and the value at the clamp is exactly +-1 (tanh
  // rounds to it there) whether the compiler fuses the multiply-adds (the AVX2 and AVX-512 kernels)
  // or not (SSE2, the tests): below it neither form exceeds 1. The clamp and the last coefficient
  // of p (3 ulp above Eigen's) were searched for that (an error of at most 4.2e-7 over every float
  // in [0, 9], both forms); with Eigen's, the fused form stopped at 1 - 2.4e-7, and a saturated
  // unit kept a derivative of 4.8e-7 that large inputs turned into full Adam steps.
  const T x = clamp_symmetric(in, 8.01393985748291016f);
  const T x2 = x * x;
  T p = x2 * -2.76076847742355e-16f + 2.00018790482477e-13f;
  p = x2 * p + -8.60467152213735e-11f;
  p = x2 * p + 5.12229709037114e-08f;
  p = x2 * p + 1.48572235717979e-05f;
  p = x2 * p + 6.37261928875436e-04f;
  p = x2 * p + 4.89352596923708916e-03f;
  p = x * p;
  T q = x2 * 1.19825839466702e-06f + 1.18534705686654e-04f;
  q = x2 * q + 2.26843463243900e-03f;
  q = x2 * q + 4.89352518554385e-03f;
  return p / q;
}

}  // namespace sn::nn

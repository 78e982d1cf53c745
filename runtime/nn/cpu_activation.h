// The built-in activations (nn/activation_builtin.cpp) as SIMD code for the cpu backend, one
// sample per lane of a GCC vector (v8: eight lanes for AVX2 and SSE2, v16: sixteen for AVX-512),
// with the elementary functions they need written in the same vector arithmetic (Cephes-style
// range reductions and minimax polynomials): exp, log(1 + u) on [0, 1], sin and cos. Included
// only by nn/cpu_net.cpp, inside its kernels' instruction-set targets.
//
// act_both<K> gives a = f(z) and f'(z) from one evaluation (sine shares its range reduction with
// cos, gelu its tanh, swish its sigmoid). For kinds whose derivative follows from a (kFromOutput)
// the backward pass calls act_grad_a<K> instead and the forward pass stores no derivative.
#pragma once
#include <immintrin.h>

#include <type_traits>

#include "nn/activation.h"
#include "nn/fast_tanh.h"

namespace sn::nn::simd {

typedef float v8 __attribute__((vector_size(32)));
typedef int v8i __attribute__((vector_size(32)));
typedef float v16 __attribute__((vector_size(64)));
typedef int v16i __attribute__((vector_size(64)));
#define SN_INLINE inline __attribute__((always_inline))
// A lambda's body is a function of its own, outside the kernel's instruction-set target: only
// when always inlined does it compile (and run) with the kernel's instructions.
#define SN_INLINE_LAMBDA __attribute__((always_inline))

// The lane mask type of a vector (what its comparisons give).
template <class V>
using mask_of = decltype(V{} > 0.0f);

// A broadcast, written as a shuffle: GCC 12 compiles the 8-element constructor (and x - 0)
// into insert chains, which cost 15-30% of a training step.
// (Clang, which builds the fuzz targets, has no __builtin_shuffle and broadcasts either way.)
template <class V = v8, class T = float>
SN_INLINE V splat(T x) {
#ifdef __clang__
  return V{} + x;
#else
  V v{};
  v[0] = x;
  return __builtin_shuffle(v, mask_of<V>{});
#endif
}

struct Avx512 {};
struct Avx2 {};
struct Sse2 {};

// sqrt per lane; the Sse2 form (two 4-lane halves) is correct under any target.
template <class Isa>
SN_INLINE v8 vsqrt(const v8& x) {
  if constexpr (!std::is_same_v<Isa, Sse2>) {
    return (v8)__builtin_ia32_sqrtps256((__m256)x);
  } else {
    typedef float v4 __attribute__((vector_size(16)));
    v4 lo = {x[0], x[1], x[2], x[3]}, hi = {x[4], x[5], x[6], x[7]};
    lo = (v4)_mm_sqrt_ps((__m128)lo);
    hi = (v4)_mm_sqrt_ps((__m128)hi);
    return v8{lo[0], lo[1], lo[2], lo[3], hi[0], hi[1], hi[2], hi[3]};
  }
}
// Only the AVX-512 kernels use 16 lanes. (Clang, which builds the fuzz targets, checks its
// 512-bit builtin against the template's own target, so there it takes two 8-lane halves.)
template <class Isa>
SN_INLINE v16 vsqrt(const v16& x) {
  static_assert(std::is_same_v<Isa, Avx512>, "16 lanes are the AVX-512 kernels'");
#ifdef __clang__
  const v8 lo = vsqrt<Avx2>(v8(__builtin_shufflevector(x, x, 0, 1, 2, 3, 4, 5, 6, 7)));
  const v8 hi = vsqrt<Avx2>(v8(__builtin_shufflevector(x, x, 8, 9, 10, 11, 12, 13, 14, 15)));
  return __builtin_shufflevector(lo, hi, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
#else
  return (v16)__builtin_ia32_sqrtps512_mask((__v16sf)x, (__v16sf)x, (__mmask16)-1, _MM_FROUND_CUR_DIRECTION);
#endif
}
// The instruction set whose sqrt is correct for V under its kernels' target.
template <class V>
using sqrt_isa = std::conditional_t<sizeof(V) == 64, Avx512, Sse2>;

template <class M, class V>
SN_INLINE V select(const M& mask, const V& yes, const V& no) { return mask ? yes : no; }

// Round to nearest (ties away from 0) as integers and as floats; |x| < 2^31.
template <class V>
SN_INLINE mask_of<V> round_int(const V& x) {
  return __builtin_convertvector(x + select(x >= 0.0f, splat<V>(0.5f), splat<V>(-0.5f)), mask_of<V>);
}

// e^x, relative error ~2e-7; 0 below -87.3 (clamped to the smallest normal's range), +inf above
// 88.7; NaN stays NaN.
template <class V>
SN_INLINE V vexp(const V& in) {
  V x = in;
  const mask_of<V> over = x > 88.72283f;
  x = select(x < -87.33654f, splat<V>(-87.33654f), x);
  x = select(over, splat<V>(0.0f), x);
  const mask_of<V> n = round_int(x * 1.44269504088896341f);
  const V fn = __builtin_convertvector(n, V);
  x = x - fn * 0.693359375f;
  x = x - fn * -2.12194440e-4f;
  V y = x * 1.9875691500e-4f + 1.3981999507e-3f;
  y = y * x + 8.3334519073e-3f;
  y = y * x + 4.1665795894e-2f;
  y = y * x + 1.6666665459e-1f;
  y = y * x + 5.0000001201e-1f;
  y = y * (x * x) + x + 1.0f;
  // 2^n as 2 * 2^(n-1): n reaches 128 just below the overflow threshold. n - 1 + 127 is in
  // [0, 254]; masked to 8 bits, a NaN input's n = INT_MIN (its y is NaN anyway) shifts no
  // bit into the sign (UB).
  y = (y + y) * (V)(((n + 126) & 255) << 23);
  return select(over, splat<V>(__builtin_inff()), y);
}

// log(1 + u) for u in [-0.3, 1] as 2 atanh(s), s = u / (2 + u) in [-0.18, 1/3]: an odd series whose
// terms past s^13 are below 1e-8, exact near u = 0 (no cancellation).
template <class V>
SN_INLINE V vlog1p_unit(const V& u) {
  const V s = u / (u + 2.0f), s2 = s * s;
  V p = s2 * (1.0f / 13) + (1.0f / 11);
  p = p * s2 + (1.0f / 9);
  p = p * s2 + (1.0f / 7);
  p = p * s2 + (1.0f / 5);
  p = p * s2 + (1.0f / 3);
  p = p * s2 + 1.0f;
  return 2.0f * s * p;
}

// log x as x = m 2^e with m in [sqrt(1/2), sqrt(2)): log m = log(1 + u) by the series above (its
// s = u / (2 + u) stays within 0.18, and there is no cancellation near x = 1), plus e ln 2 in two
// parts. 0 gives -inf (denormals too: the kernels flush them), x < 0 and NaN give NaN, inf inf.
template <class V>
SN_INLINE V vlog(const V& x) {
  using I = mask_of<V>;
  const I bits = (I)x;
  I e = ((bits >> 23) & 255) - 127;
  V m = (V)((bits & 0x7fffff) | 0x3f800000);  // [1, 2)
  const I big = m > 1.41421356f;  // -1 where true
  m = select(big, m * 0.5f, m);
  e -= big;
  const V fe = __builtin_convertvector(e, V);
  const V y = (vlog1p_unit(m - 1.0f) + fe * -2.12194440e-4f) + fe * 0.693359375f;
  const V special = select(x == 0.0f, splat<V>(-__builtin_inff()), splat<V>(__builtin_nanf("")));
  return select(x == __builtin_inff(), x, select(x > 0.0f, y, special));
}

// sin x and cos x: x - n pi/2 in three parts (Cody-Waite), then the Cephes polynomials on
// [-pi/4, pi/4]; absolute error ~1e-7 for |x| up to 8192. Beyond, n pi/2 is no longer exact in
// three parts and the remainder drifts (errors up to 2.5e-3 by 1e6, 0.29 by 1.7e7; past 2^31 n is
// INT_MIN, x86's conversion of a value out of range), so the remainder is clamped to pi/4: the
// polynomials stay in [-1, 1] (sin reached 13.3 and -inf), and no value for |x| <= 8192 changes.
// Taking the lanes past 8192 in double instead halved a sine network's training speed, the
// test alone (docs/performance.md, "Tried and dropped"): the range is documented instead.
template <class V>
SN_INLINE void vsincos(const V& x, V& s_out, V& c_out) {
  const mask_of<V> n = round_int(x * 0.636619772367581343f);
  const V fn = __builtin_convertvector(n, V);
  V r = x - fn * 1.5703125f;
  r = r - fn * 4.837512969970703125e-4f;
  r = clamp_symmetric(r - fn * 7.54978995489188216e-8f, 0.785398185f);
  const V r2 = r * r;
  V s = r2 * -1.9515295891e-4f + 8.3321608736e-3f;
  s = s * r2 + -1.6666654611e-1f;
  s = s * r2 * r + r;
  V c = r2 * 2.443315711809948e-5f + -1.388731625493765e-3f;
  c = c * r2 + 4.166664568298827e-2f;
  c = c * r2 * r2 - 0.5f * r2 + 1.0f;
  const mask_of<V> q = n & 3;
  // sin x: q 0 -> s, 1 -> c, 2 -> -s, 3 -> -c; cos x: q 0 -> c, 1 -> -s, 2 -> -c, 3 -> s.
  const mask_of<V> odd = (q & 1) != 0;
  const V sx = select(odd, c, s), cx = select(odd, -s, c);
  s_out = select((q & 2) != 0, -sx, sx);
  c_out = select((q & 2) != 0, -cx, cx);
}

// atan x (Cephes' atanf): |x| reduced to [0, tan(pi/8)] by pi/2 - atan(1/x) or pi/4 + atan((x - 1)
// / (x + 1)), then an odd polynomial; relative error ~2e-7. +-inf gives +-pi/2, NaN NaN.
template <class V>
SN_INLINE V vatan(const V& in) {
  const mask_of<V> negative = in < 0.0f;
  V x = select(negative, -in, in);
  const mask_of<V> far = x > 2.414213562373095f, mid = (x > 0.4142135623730950f) & ~far;
  const V y0 = select(far, splat<V>(1.5707963267948966f), select(mid, splat<V>(0.7853981633974483f), splat<V>(0.0f)));
  x = select(far, -1.0f / x, select(mid, (x - 1.0f) / (x + 1.0f), x));
  const V z = x * x;
  V y = z * 8.05374449538e-2f - 1.38776856032e-1f;
  y = y * z + 1.99777106478e-1f;
  y = y * z - 3.33329491539e-1f;
  y = y * z * x + x + y0;
  return select(negative, -y, y);
}

// The logistic function two ways: through fast_tanh (absolute error 5e-7; sigmoid's own, as
// before), and through vexp (relative error ~3e-7: swish multiplies it by z).
template <class V>
SN_INLINE V vsigmoid(const V& z) { return 0.5f + 0.5f * fast_tanh(0.5f * z); }
template <class V>
SN_INLINE V vsigmoid_exp(const V& z) { return 1.0f / (1.0f + vexp(-z)); }

// softplus keeps f'(z) too: its forward pass has e^-|z| at hand, from which sigmoid(z) costs one
// division, where 1 - e^-a from the output would cost another exp.
template <int K>
constexpr bool kFromOutput = K != int(Builtin::sine) && K != int(Builtin::gelu) && K != int(Builtin::swish) &&
                             K != int(Builtin::softplus);

constexpr float kGeluC = 0.7978845608028654f, kGeluK = 0.044715f;

// a = f(z) and g = f'(z); z by value, so that a may be z's own storage.
template <int K, class V>
SN_INLINE void act_both(const V z, float p, V& a, V& g) {
  constexpr Builtin B = Builtin(K);
  if constexpr (B == Builtin::tanh) {
    a = fast_tanh(z);
    g = 1.0f - a * a;
  } else if constexpr (B == Builtin::sigmoid) {
    a = vsigmoid(z);
    g = a * (1.0f - a);
  } else if constexpr (B == Builtin::relu) {
    a = select(z < 0.0f, splat<V>(0.0f), z);  // NaN stays NaN
    g = select(z > 0.0f, splat<V>(1.0f), splat<V>(0.0f));
  } else if constexpr (B == Builtin::leaky_relu) {
    a = select(z > 0.0f, z, p * z);
    g = select(z > 0.0f, splat<V>(1.0f), splat<V>(p));
  } else if constexpr (B == Builtin::sine) {
    vsincos(p * z, a, g);
    g = p * g;
  } else if constexpr (B == Builtin::softplus) {
    const V e = vexp(select(z > 0.0f, -z, z));  // e^-|z|
    a = select(z > 0.0f, z, splat<V>(0.0f)) + vlog1p_unit(e);
    g = select(z > 0.0f, splat<V>(1.0f), e) / (1.0f + e);  // sigmoid(z)
  } else if constexpr (B == Builtin::squareplus) {
    // z^2 overflows past 1.8e19: clamped to 1e18 inside the root, f = z beyond (as the GLSL).
    const V c = clamp_symmetric(z, 1e18f), s = vsqrt<sqrt_isa<V>>(c * c + 4.0f);
    a = select(z >= 0.0f, select(z > 1e18f, z, 0.5f * (z + s)), 2.0f / (s - z));
    g = 0.5f + 0.5f * c / s;
  } else if constexpr (B == Builtin::elu) {
    const V e = vexp(select(z > 0.0f, splat<V>(0.0f), z));
    a = select(z > 0.0f, z, p * (e - 1.0f));
    g = select(z > 0.0f, splat<V>(1.0f), p * e);
  } else if constexpr (B == Builtin::gelu) {
    const V z2 = z * z;
    const V u = kGeluC * (z + kGeluK * z2 * z);
    // Exactly +-1 where tanh rounds there: fast_tanh's last ulp, times z^3 in f', is not 0.
    const V t = select(u > 9.0f, splat<V>(1.0f), select(u < -9.0f, splat<V>(-1.0f), fast_tanh(u)));
    a = 0.5f * z * (1.0f + t);
    // z clamped where 1 - t^2 is 0 anyway: z^2 past 1.8e19 made 0 * inf (activation_builtin.cpp).
    const V c = clamp_symmetric(z, 10.0f), c2 = c * c;
    g = 0.5f * (1.0f + t) + (0.5f * kGeluC) * c * (1.0f - t * t) * (1.0f + 3.0f * kGeluK * c2);
  } else if constexpr (B == Builtin::swish) {
    const V s = vsigmoid_exp(z);
    a = z * s;
    g = s * (1.0f + z * (1.0f - s));
  } else if constexpr (B == Builtin::exponential) {
    a = vexp(z);
    g = a;
  } else {
    a = z;
    g = splat<V>(1.0f);
  }
}

template <int K, class V>
SN_INLINE V act(const V& z, float p) {
  constexpr Builtin B = Builtin(K);
  if constexpr (B == Builtin::tanh) return fast_tanh(z);
  if constexpr (B == Builtin::sigmoid) return vsigmoid(z);
  if constexpr (B == Builtin::relu) return select(z < 0.0f, splat<V>(0.0f), z);
  if constexpr (B == Builtin::leaky_relu) return select(z > 0.0f, z, p * z);
  if constexpr (B == Builtin::linear) return z;
  V a, g;
  act_both<K>(z, p, a, g);  // the compiler drops the unused derivative
  return a;
}

// f'(z) from a = f(z), for kFromOutput kinds.
template <int K, class V>
SN_INLINE V act_grad_a(const V& a, float p) {
  constexpr Builtin B = Builtin(K);
  static_assert(kFromOutput<K>, "this activation's derivative needs z");
  if constexpr (B == Builtin::tanh) return 1.0f - a * a;
  if constexpr (B == Builtin::sigmoid) return a * (1.0f - a);
  if constexpr (B == Builtin::relu) return select(a > 0.0f, splat<V>(1.0f), splat<V>(0.0f));
  if constexpr (B == Builtin::leaky_relu) return select(a > 0.0f, splat<V>(1.0f), splat<V>(p));
  if constexpr (B == Builtin::squareplus) {
    const V c = clamp_symmetric(a, 1e18f);  // a >= 0; a^2 overflowed to inf / inf
    return c * c / (c * c + 1.0f);
  }
  if constexpr (B == Builtin::elu) return select(a > 0.0f, splat<V>(1.0f), a + p);
  if constexpr (B == Builtin::exponential) return a;
  return splat<V>(1.0f);
}

// The output layer's activation is chosen per neuron at run time (few neurons, cheap).
template <class F>
SN_INLINE void with_builtin(int kind, F&& f) {
  switch (Builtin(kind)) {
    case Builtin::tanh: f(std::integral_constant<int, int(Builtin::tanh)>{}); break;
    case Builtin::sigmoid: f(std::integral_constant<int, int(Builtin::sigmoid)>{}); break;
    case Builtin::relu: f(std::integral_constant<int, int(Builtin::relu)>{}); break;
    case Builtin::leaky_relu: f(std::integral_constant<int, int(Builtin::leaky_relu)>{}); break;
    case Builtin::sine: f(std::integral_constant<int, int(Builtin::sine)>{}); break;
    case Builtin::softplus: f(std::integral_constant<int, int(Builtin::softplus)>{}); break;
    case Builtin::squareplus: f(std::integral_constant<int, int(Builtin::squareplus)>{}); break;
    case Builtin::elu: f(std::integral_constant<int, int(Builtin::elu)>{}); break;
    case Builtin::gelu: f(std::integral_constant<int, int(Builtin::gelu)>{}); break;
    case Builtin::swish: f(std::integral_constant<int, int(Builtin::swish)>{}); break;
    case Builtin::exponential: f(std::integral_constant<int, int(Builtin::exponential)>{}); break;
    default: f(std::integral_constant<int, int(Builtin::linear)>{}); break;
  }
}

template <class V>
SN_INLINE V act_any(int kind, const V& z, float p) {
  V a;
  with_builtin(kind, [&](auto k) SN_INLINE_LAMBDA { a = act<decltype(k)::value>(z, p); });
  return a;
}
template <class V>
SN_INLINE void act_both_any(int kind, const V z, float p, V& a, V& g) {
  with_builtin(kind, [&](auto k) SN_INLINE_LAMBDA { act_both<decltype(k)::value>(z, p, a, g); });
}
// kFromOutput and act_grad_a for a kind chosen at run time.
inline bool from_output_any(int kind) {
  bool yes = false;
  with_builtin(kind, [&](auto k) SN_INLINE_LAMBDA { yes = kFromOutput<decltype(k)::value>; });
  return yes;
}
template <class V>
SN_INLINE V act_grad_a_any(int kind, const V& a, float p) {
  V g = a;
  with_builtin(kind, [&](auto k) SN_INLINE_LAMBDA {
    if constexpr (kFromOutput<decltype(k)::value>) g = act_grad_a<decltype(k)::value>(a, p);
  });
  return g;
}

}  // namespace sn::nn::simd

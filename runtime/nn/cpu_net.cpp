// The 32-byte vectors below never cross a non-inlined call, so GCC's ABI note does not apply;
// GCC 12 reports the register accumulators of rows_forward as maybe-uninitialized once splat's
// shuffle is inlined (every element is assigned before use: a false positive).
#pragma GCC diagnostic ignored "-Wpsabi"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

#include "nn/cpu_net.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <cstdlib>
#include <cstring>
#include <new>

#include "nn/cpu_activation.h"
#include "nn/cpu_expr.h"

namespace sn::nn {

namespace {

using namespace simd;

constexpr int kMaxLanes = 16;  // the widest vectors' lanes (v16): the scratch is sized for them
std::size_t round4(std::size_t n) { return (n + 3) & ~std::size_t(3); }
std::size_t round8(std::size_t n) { return (n + 7) & ~std::size_t(7); }
std::size_t round16(std::size_t n) { return (n + 15) & ~std::size_t(15); }

}  // namespace

// Padded offsets, in floats. Parameters (per network): layer l = rows [out][inpad] (inpad = in
// rounded up to 4, pad columns stay 0; the weight gradient runs over them in vectors of 8 inputs
// and a last one of 4, so rounding to 8 made Adam and the gradient of widths 10 and 12 work on
// a quarter to three eighths of pad), then biases [round8(out)] from a multiple of 8; so every
// layer and bias block starts at a multiple of 8 (32 bytes; a pair's, of 16), and a copy is
// rounded up to 16 floats for Adam's 16-lane vectors (rounding each layer instead cost 10% more
// Adam work for 8x8). A pair of networks interleaves two such copies float by float. The scratch
// (activations, their derivatives, transposes, errors, targets) has room for 16 lanes per unit,
// in multiples of 16; its transposed activations have rows of tpad = in rounded up to 8.
struct CpuNet::Layout {
  int L = 0;
  int in[kMaxHidden + 1] = {}, out[kMaxHidden + 1] = {}, inpad[kMaxHidden + 1] = {}, tpad[kMaxHidden + 1] = {};
  std::size_t woff[kMaxHidden + 1] = {}, boff[kMaxHidden + 1] = {};  // within a parameter copy
  std::size_t P = 0;  // floats per parameter copy of one network
  std::size_t aoff[kMaxHidden + 2] = {};  // activations of layer l (width(l) x 16), from the scratch
  std::size_t toff[kMaxHidden + 1] = {};  // transposed activations (16 x tpad), from o_at
  int maxw = 0;
  // o_dz: f'(z) of every unit, same offsets as the activations (stored by a training forward
  // pass for hidden kinds that need z, and for the output layer).
  std::size_t o_dz = 0, o_at = 0, o_d[2] = {}, o_t = 0, scratch = 0;  // o_t: a block's targets
  // Builtin ids (their SIMD code), or kTranslated: a user's definition, whose translated f, and
  // f with f', are held here (so that redefining the name cannot pull them from a running kernel).
  int hidden = int(Builtin::tanh), output = int(Builtin::linear);
  std::shared_ptr<const ActivationExpr> hf, hb, of, ob;
  float hp = 0, op = 0;  // their parameters

  explicit Layout(const MlpSpec& s) {
    L = s.layers();
    auto kind = [](Activation a, std::shared_ptr<const ActivationExpr>& f, std::shared_ptr<const ActivationExpr>& both) {
      const ActivationDef& d = activation_def(a);
      if (d.simd >= 0) return d.simd;
      if (!d.cpu_f) throw std::invalid_argument(activation_without_cpu_code(a) + ": train it with backend = \"gl\"");
      f = d.cpu_f, both = d.cpu_both;
      return kTranslated;
    };
    hidden = kind(s.activation, hf, hb);
    output = kind(s.output_activation, of, ob);
    hp = float(s.param(s.activation));
    op = float(s.param(s.output_activation));
    maxw = s.max_width();
    std::size_t at = 0, a = 0;
    for (int l = 0; l < L; ++l) {
      in[l] = s.width(l);
      out[l] = s.width(l + 1);
      inpad[l] = int(round4(in[l]));
      tpad[l] = int(round8(in[l]));
      woff[l] = P;
      boff[l] = round8(P + std::size_t(out[l]) * inpad[l]);
      P = boff[l] + round8(out[l]);
      toff[l] = at;
      at += round16(std::size_t(kMaxLanes) * tpad[l]);
    }
    P = round16(P);
    for (int l = 0; l <= L; ++l) {
      aoff[l] = a;
      a += round16(std::size_t(s.width(l)) * kMaxLanes);
    }
    const std::size_t d = round16(std::size_t(maxw) * kMaxLanes);
    std::size_t o = a;
    o_dz = o, o += a;
    o_at = o, o += at;
    o_d[0] = o, o += d;
    o_d[1] = o, o += d;
    o_t = o, o += round16(std::size_t(out[L - 1]) * kMaxLanes);
    scratch = o;
  }
  // Parameter copies 0 and 1, Adam's m and v, the gradient: 5 P floats per network.
  std::size_t params(int nets) const { return 5 * P * std::size_t(nets); }
};

namespace {

using Layout = CpuNet::Layout;

// How a kernel's vectors hold samples, and where a weight comes from.
//  One:  8 samples of one network per v8; a weight is broadcast to every lane.
//  Pair: 8 samples of each of two networks per v16, interleaved (lane 2s + h is sample s of
//        network h), and their parameters interleaved alike (kPar = 2 floats per parameter): a
//        weight pair is one 64-bit broadcast. Two networks of one architecture in one job (a
//        sweep's seeds, each reading its own rows) fill AVX-512 registers at batch 8.
//  Wide: 16 samples of one network per v16 (inference).
// G: the weight gradient's vectors, which hold 8 inputs (of each network); Gh: 4 inputs.
typedef double v8d __attribute__((vector_size(64)));
typedef float v4 __attribute__((vector_size(16)));
typedef double v4d __attribute__((vector_size(32)));
struct One {
  using V = v8;
  using G = v8;
  using Gh = v4;  // 4 inputs: a row's last vector when its inputs are 4 more than a multiple of 8
  using E = v8;  // a vector as 8 units of kPar floats (the transposes' view)
  static constexpr int kPar = 1, kSamples = 8;
  static SN_INLINE V w(const float* p) { return splat<V>(*p); }
  static SN_INLINE Gh wh(const float* p) { return Gh{*p, *p, *p, *p}; }
};
// A weight as one vbroadcastss from memory (AVX's instruction, so not in the sse2 kernel, whose
// One keeps splat): GCC builds splat's vector in two instructions (an insert and a shuffle), a
// constructor's in one masked load per lane, and a target attribute on w cannot be inlined into
// the templates the kernels share. Clang (the fuzzing build) makes splat one broadcast, and
// refuses a 64-byte asm operand outside an AVX-512 function.
template <class V>
SN_INLINE V broadcast_from(const float* p) {
#ifdef __clang__
  return splat<V>(*p);
#else
  V r;
  __asm__("vbroadcastss %1, %0" : "=v"(r) : "m"(*p));
  return r;
#endif
}
struct OneAvx : One {  // One in the AVX2 and AVX-512 kernels
  static SN_INLINE V w(const float* p) { return broadcast_from<V>(p); }
};
struct Wide {  // inference only: no gradient
  using V = v16;
  static constexpr int kPar = 1, kSamples = 16;
  static SN_INLINE V w(const float* p) { return broadcast_from<V>(p); }
};
struct Pair {
  using V = v16;
  using G = v16;
  using Gh = v8;
  using E = v8d;
  static constexpr int kPar = 2, kSamples = 8;
  // A weight pair as one double, broadcast: one vbroadcastsd from memory (splat's shuffle made two).
  static SN_INLINE double pair_at(const float* p) {
    double d;
    std::memcpy(&d, p, sizeof d);
    return d;
  }
  static SN_INLINE V w(const float* p) {
    const double d = pair_at(p);
    return (V)v8d{d, d, d, d, d, d, d, d};
  }
  static SN_INLINE Gh wh(const float* p) {
    const double d = pair_at(p);
    return (Gh)v4d{d, d, d, d};
  }
};
template <class Mode>
constexpr int kLanesOf = int(sizeof(typename Mode::V) / sizeof(float));

// Transposes 8 rows of 8 units in registers (E: v8, float units, or v8d, 64-bit units: a
// pair's two networks move together), in three rounds of interleaving.
template <class E>
SN_INLINE void transpose8(E r[8]) {
  E t[8];
  for (int i = 0; i < 8; i += 2) {
    t[i] = __builtin_shufflevector(r[i], r[i + 1], 0, 8, 2, 10, 4, 12, 6, 14);
    t[i + 1] = __builtin_shufflevector(r[i], r[i + 1], 1, 9, 3, 11, 5, 13, 7, 15);
  }
  for (int i : {0, 1, 4, 5}) {
    r[i] = __builtin_shufflevector(t[i], t[i + 2], 0, 1, 8, 9, 4, 5, 12, 13);
    r[i + 2] = __builtin_shufflevector(t[i], t[i + 2], 2, 3, 10, 11, 6, 7, 14, 15);
  }
  for (int i = 0; i < 4; ++i) {
    t[i] = __builtin_shufflevector(r[i], r[i + 4], 0, 1, 2, 3, 8, 9, 10, 11);
    t[i + 4] = __builtin_shufflevector(r[i], r[i + 4], 4, 5, 6, 7, 12, 13, 14, 15);
  }
  for (int i = 0; i < 8; ++i) r[i] = t[i];
}

// The sum of a block's 8 lanes, in the order the bias gradient's transposed sums use, in double:
// in float, eight squared errors of 4.9e37 overflowed, and the validation MSE was inf (an
// "exploded" net) where gl's was finite.
SN_INLINE double hsum_double(const v8& v) {
  auto d = [&](int i) { return double(v[i]); };
  return ((d(0) + d(4)) + (d(1) + d(5))) + ((d(2) + d(6)) + (d(3) + d(7)));
}

// Where a kernel finds everything of one network, or of a pair.
struct Arena {
  const Layout& S;
  float* par;      // parameter copies 0 and 1, m, v, gradient (a pair's interleaved)
  float* scratch;  // activations and the rest (Layout::scratch floats)
  int cur;         // which parameter copy is current
};
template <class Mode>
struct View {
  using Vec = typename Mode::V;
  static constexpr std::size_t k = Mode::kPar;
  const Layout& S;
  float* par;
  float* scratch;
  int cur;
  explicit View(const Arena& a) : S(a.S), par(a.par), scratch(a.scratch), cur(a.cur) {}
  float* p() const { return par + std::size_t(cur) * S.P * k; }
  float* pnext() const { return par + std::size_t(cur ^ 1) * S.P * k; }
  float* m() const { return par + 2 * S.P * k; }
  float* v() const { return par + 3 * S.P * k; }
  float* g() const { return par + 4 * S.P * k; }
  Vec* act(int l) const { return reinterpret_cast<Vec*>(scratch + S.aoff[l]); }
  Vec* dz(int l) const { return reinterpret_cast<Vec*>(scratch + S.o_dz + S.aoff[l]); }
  float* at(int l) const { return scratch + S.o_at + S.toff[l]; }
  Vec* d(int i) const { return reinterpret_cast<Vec*>(scratch + S.o_d[i]); }
  Vec* t() const { return reinterpret_cast<Vec*>(scratch + S.o_t); }
};

// put(j, b[j] + sum_i W[j][i] a[i]) for R rows at once (R independent FMA chains; put applies the
// activation and stores). The accumulators are named variables, not an array: GCC kept an array
// acc[R] in memory for R < 8 (a store and a load around every FMA; 4x4 networks ran at half speed).
template <int R, class Mode, class Put>
SN_INLINE void rows_forward(const float* W, int inpad, const float* b, int in, const typename Mode::V* a,
                            const Put& put) {
  using Vec = typename Mode::V;
  constexpr int k = Mode::kPar;
  const std::size_t st = std::size_t(inpad) * k;
  const Vec zero = splat<Vec>(0.0f);
  Vec c0 = R > 0 ? Mode::w(b) : zero, c1 = R > 1 ? Mode::w(b + k) : zero, c2 = R > 2 ? Mode::w(b + 2 * k) : zero,
      c3 = R > 3 ? Mode::w(b + 3 * k) : zero, c4 = R > 4 ? Mode::w(b + 4 * k) : zero,
      c5 = R > 5 ? Mode::w(b + 5 * k) : zero, c6 = R > 6 ? Mode::w(b + 6 * k) : zero,
      c7 = R > 7 ? Mode::w(b + 7 * k) : zero;
  for (int i = 0; i < in; ++i) {
    const Vec ai = a[i];
    const float* w = W + i * k;
    if constexpr (R > 0) c0 += Mode::w(w) * ai;
    if constexpr (R > 1) c1 += Mode::w(w + st) * ai;
    if constexpr (R > 2) c2 += Mode::w(w + 2 * st) * ai;
    if constexpr (R > 3) c3 += Mode::w(w + 3 * st) * ai;
    if constexpr (R > 4) c4 += Mode::w(w + 4 * st) * ai;
    if constexpr (R > 5) c5 += Mode::w(w + 5 * st) * ai;
    if constexpr (R > 6) c6 += Mode::w(w + 6 * st) * ai;
    if constexpr (R > 7) c7 += Mode::w(w + 7 * st) * ai;
  }
  if constexpr (R > 0) put(0, c0);
  if constexpr (R > 1) put(1, c1);
  if constexpr (R > 2) put(2, c2);
  if constexpr (R > 3) put(3, c3);
  if constexpr (R > 4) put(4, c4);
  if constexpr (R > 5) put(5, c5);
  if constexpr (R > 6) put(6, c6);
  if constexpr (R > 7) put(7, c7);
}

// prev[j] = f'(z_j) sum_o W[o][j] d[o] for R columns at once (grad(j): f'(z_j), applied before
// the store: a separate pass would store, load and store every unit again).
template <int R, class Mode, class Grad>
SN_INLINE void cols_backward(const float* W, int inpad, int out, const typename Mode::V* d, typename Mode::V* prev,
                             const Grad& grad) {
  using Vec = typename Mode::V;
  constexpr int k = Mode::kPar;
  Vec acc[R];
  for (int j = 0; j < R; ++j) acc[j] = splat<Vec>(0.0f);
  for (int o = 0; o < out; ++o) {
    const Vec dv = d[o];
    for (int j = 0; j < R; ++j) acc[j] += Mode::w(W + (std::size_t(o) * inpad + j) * k) * dv;
  }
  for (int j = 0; j < R; ++j) prev[j] = acc[j] * grad(j);
}

// G[j][c..c+N) (+)= sum_s d[j][s] * aT[s][c..c+N) for R rows, N = the inputs of a vector Gv
// (of each network). G's rows (inpad floats) start anywhere a multiple of 4 floats falls.
template <int R, class Mode, bool kAdd, class Gv, class W>
SN_INLINE void rows_gradient_at(int c, float* G, int inpad, int tpad, const float* d, const float* aT, const W& w) {
  typedef Gv Gu __attribute__((aligned(16)));
  constexpr int k = Mode::kPar, lanes = kLanesOf<Mode>;
  Gv acc[R];
  for (int j = 0; j < R; ++j) acc[j] = kAdd ? *reinterpret_cast<const Gu*>(G + (std::size_t(j) * inpad + c) * k) : Gv{};
  for (int s = 0; s < Mode::kSamples; ++s) {
    const Gv a = *reinterpret_cast<const Gv*>(aT + (std::size_t(s) * tpad + c) * k);
    for (int j = 0; j < R; ++j) acc[j] += w(d + j * lanes + s * k) * a;
  }
  for (int j = 0; j < R; ++j) *reinterpret_cast<Gu*>(G + (std::size_t(j) * inpad + c) * k) = acc[j];
}

// G[j][:] += sum_s d[j][s] * aT[s][:] for R rows: the weight gradient as outer products, with
// the minibatch (s) as the reduction and 8 inputs (of each network) per vector; the last 4 of
// a row whose inpad is not a multiple of 8 are gradient_tail's. kAdd false: G[j][:] = the sum
// (a minibatch's first block, so the gradient needs no clearing per step). aT's rows are tpad
// floats (aligned).
template <int R, class Mode, bool kAdd>
SN_INLINE void rows_gradient(float* G, int inpad, int tpad, const float* d, const float* aT) {
  for (int c = 0; c + 8 <= inpad; c += 8)
    rows_gradient_at<R, Mode, kAdd, typename Mode::G>(c, G, inpad, tpad, d, aT,
                                                     [](const float* p) SN_INLINE_LAMBDA { return Mode::w(p); });
}

// The last 4 inputs of every row, where inpad is 4 more than a multiple of 8: four rows at a
// time, then one (a copy per group size of in_groups grew the step past the instruction cache:
// 8x8 networks, which never come here, trained 2% slower; one row at a time loads aT 4 times
// as often).
template <class Mode, bool kAdd>
SN_INLINE void gradient_tail(int out, float* G, int inpad, int tpad, const float* d, const float* aT) {
  const int c = inpad & ~7;
  if (c == inpad) return;
  const auto wh = [](const float* p) SN_INLINE_LAMBDA { return Mode::wh(p); };
  using Gh = typename Mode::Gh;
  int j = 0;
  for (; j + 4 <= out; j += 4)
    rows_gradient_at<4, Mode, kAdd, Gh>(c, G + std::size_t(j) * inpad * Mode::kPar, inpad, tpad, d + j * kLanesOf<Mode>, aT, wh);
  for (; j < out; ++j)
    rows_gradient_at<1, Mode, kAdd, Gh>(c, G + std::size_t(j) * inpad * Mode::kPar, inpad, tpad, d + j * kLanesOf<Mode>, aT, wh);
}

// Runs F<R, Mode>(first, R) over [0, n) in groups of 8 and one remainder group.
template <template <int, class> class F, class Mode, class... Args>
SN_INLINE void in_groups(int n, Args&&... args) {
  int j = 0;
  for (; j + 8 <= n; j += 8) F<8, Mode>::run(j, args...);
  switch (n - j) {
    case 7: F<7, Mode>::run(j, args...); break;
    case 6: F<6, Mode>::run(j, args...); break;
    case 5: F<5, Mode>::run(j, args...); break;
    case 4: F<4, Mode>::run(j, args...); break;
    case 3: F<3, Mode>::run(j, args...); break;
    case 2: F<2, Mode>::run(j, args...); break;
    case 1: F<1, Mode>::run(j, args...); break;
    default: break;
  }
}
template <int R, class Mode>
struct Forward {
  using Vec = typename Mode::V;
  template <class Put>
  static SN_INLINE void run(int o, const float* W, int inpad, const float* b, int in, const Vec* a, const Put& put) {
    rows_forward<R, Mode>(W + std::size_t(o) * inpad * Mode::kPar, inpad, b + o * Mode::kPar, in, a,
                          [&](int j, const Vec& c) SN_INLINE_LAMBDA { put(o + j, c); });
  }
};
template <int R, class Mode>
struct Backward {
  using Vec = typename Mode::V;
  template <class Grad>
  static SN_INLINE void run(int i, const float* W, int inpad, int out, const Vec* d, Vec* prev, const Grad& grad) {
    cols_backward<R, Mode>(W + i * Mode::kPar, inpad, out, d, prev + i,
                           [&](int j) SN_INLINE_LAMBDA { return grad(i + j); });
  }
};
template <int R, class Mode, bool kAdd>
struct GradientOf {
  static SN_INLINE void run(int o, float* G, int inpad, int tpad, const float* d, const float* aT) {
    rows_gradient<R, Mode, kAdd>(G + std::size_t(o) * inpad * Mode::kPar, inpad, tpad, d + o * kLanesOf<Mode>, aT);
  }
};
template <int R, class Mode>
using Gradient = GradientOf<R, Mode, true>;
template <int R, class Mode>
using GradientFirst = GradientOf<R, Mode, false>;

// Loads `width` floats of each of the rows first .. first + n of src into dst, lane-major (float
// i of sample s at [i][s]); samples >= n are 0. The inputs go to layer 0's activations, the
// targets to their own block (gathered with the inputs, before the forward pass: their cache
// misses then overlap it).
template <class Mode>
SN_INLINE void gather_rows(float* dst, const float* src, int width, std::size_t first, int n) {
  static_assert(Mode::kPar == 1, "contiguous rows are one network's");
  constexpr int lanes = kLanesOf<Mode>;
  for (int i = 0; i < width; ++i)
    for (int s = 0; s < lanes; ++s) dst[i * lanes + s] = s < n ? src[(first + s) * width + i] : 0.0f;
}
template <class Mode>
SN_INLINE void gather_inputs(const View<Mode>& V, const float* x, std::size_t first, int n) {
  gather_rows<Mode>(reinterpret_cast<float*>(V.act(0)), x, V.S.in[0], first, n);
}
template <class Mode>
SN_INLINE void gather_targets(const View<Mode>& V, const float* y, std::size_t first, int n) {
  gather_rows<Mode>(reinterpret_cast<float*>(V.t()), y, V.S.out[V.S.L - 1], first, n);
}

// Block b of each network's packed minibatch (pack_minibatch's layout) into layer 0's
// activations and the targets: a vector copy per value, and for a pair two, interleaved
// (lane 2s + h is sample s of network h). Packing apart from the step keeps the per-float
// loads and stores of a gather out of it (a gather's scalar stores, read back as vectors at
// once, also stalled the forward pass).
template <class Mode>
SN_INLINE void load_block(const View<Mode>& V, const float* const mb[], int b) {
  using Vec = typename Mode::V;
  const int in = V.S.in[0], out = V.S.out[V.S.L - 1];
  const std::size_t at = std::size_t(b) * std::size_t(in + out) * 8;
  const auto lanes = [&](int i) SN_INLINE_LAMBDA {
    v8 a;
    std::memcpy(&a, mb[0] + at + std::size_t(i) * 8, sizeof a);
    if constexpr (Mode::kPar == 2) {
      v8 c;
      std::memcpy(&c, mb[1] + at + std::size_t(i) * 8, sizeof c);
      return (Vec)__builtin_shufflevector(a, c, 0, 8, 1, 9, 2, 10, 3, 11, 4, 12, 5, 13, 6, 14, 7, 15);
    } else {
      return a;
    }
  };
  Vec* x = V.act(0);
  for (int i = 0; i < in; ++i) x[i] = lanes(i);
  Vec* t = V.t();
  for (int o = 0; o < out; ++o) t[o] = lanes(in + o);
}

// A translated activation over n floats (nn/cpu_expr.h), compiled once per instruction set and
// called by the kernels of that set: out[i] = f(in[i]), and grad[i] = f'(in[i]) when given.
using ExprFn = void (*)(const ActivationExpr&, float, const float*, std::size_t, float*, float*);
void expr_sse2(const ActivationExpr& e, float p, const float* in, std::size_t n, float* out, float* grad) {
  run_expr(e, p, reinterpret_cast<const v8*>(in), n / 8, reinterpret_cast<v8*>(out), reinterpret_cast<v8*>(grad));
}
__attribute__((target("avx2,fma"))) void expr_avx2(const ActivationExpr& e, float p, const float* in, std::size_t n, float* out,
                                                   float* grad) {
  run_expr(e, p, reinterpret_cast<const v8*>(in), n / 8, reinterpret_cast<v8*>(out), reinterpret_cast<v8*>(grad));
}
#define SN_AVX512 __attribute__((target("avx512f,avx512vl,avx512dq,avx512bw,avx2,fma")))
SN_AVX512 void expr_avx512(const ActivationExpr& e, float p, const float* in, std::size_t n, float* out, float* grad) {
  run_expr(e, p, reinterpret_cast<const v16*>(in), n / 16, reinterpret_cast<v16*>(out), reinterpret_cast<v16*>(grad));
}

// A layer's `units` vectors through a translated activation, in place: f alone, or (g given)
// f and f'(z) into g from the program translated with the derivative.
template <class Mode>
SN_INLINE void translated(const ActivationExpr& f, const ActivationExpr& both, float p, typename Mode::V* z, int units,
                          typename Mode::V* g) {
  const std::size_t n = std::size_t(units) * kLanesOf<Mode>;
  ExprFn run = expr_avx512;
  if constexpr (std::is_same_v<Mode, One>) run = expr_sse2;
  else if constexpr (std::is_same_v<Mode, OneAvx>) run = expr_avx2;
  float* zf = reinterpret_cast<float*>(z);
  run(g ? both : f, p, zf, n, zf, reinterpret_cast<float*>(g));
}

// The forward pass; kTrain also stores f'(z) where backpropagation needs it: for hidden kinds
// whose derivative does not follow from a (sine, gelu, swish), and for a non-linear output layer.
// The hidden activation H: a Builtin id compiled into the kernel (tanh, the thesis' and the
// default, whose step is the one timed), or kAnyHidden, the layout's kind chosen per unit at run
// time. One kernel for the ten other kinds instead of ten: their code is as before and a switch
// per unit costs little beside exp, sin or a division, while each instantiation of the kernels
// costs minutes under the sanitizers.
constexpr int kAnyHidden = -1;
template <int H>
SN_INLINE bool hidden_from_output(const Layout& S) {
  if constexpr (H == kAnyHidden) return S.hidden != kTranslated && from_output_any(S.hidden);
  else return kFromOutput<H>;
}
template <int H, class V>
SN_INLINE V hidden_act(const Layout& S, const V& z) {
  if constexpr (H == kAnyHidden) return act_any(S.hidden, z, S.hp);
  else return act<H>(z, S.hp);
}
template <int H, class V>
SN_INLINE void hidden_both(const Layout& S, const V z, V& a, V& g) {
  if constexpr (H == kAnyHidden) act_both_any(S.hidden, z, S.hp, a, g);
  else act_both<H>(z, S.hp, a, g);
}

template <int H, class Mode, bool kTrain = false>
SN_INLINE void forward_block(const View<Mode>& V) {
  using Vec = typename Mode::V;
  const Layout& S = V.S;
  const float* p = V.p();
  for (int l = 0; l < S.L; ++l) {
    Vec* z = V.act(l + 1);
    auto layer = [&](const auto& put) SN_INLINE_LAMBDA {
      in_groups<Forward, Mode>(S.out[l], p + S.woff[l] * Mode::kPar, S.inpad[l], p + S.boff[l] * Mode::kPar,
                               S.in[l], V.act(l), put);
    };
    const bool hidden = l + 1 < S.L;
    if constexpr (H != kAnyHidden && kFromOutput<H>) {
      // A compiled-in kind is applied as the sums leave the registers (a pass of its own
      // stores and loads every unit again: 4% of an 8x8 step). The kinds chosen at run time
      // keep that pass: their switch, inlined at every row, would bloat each kernel tenfold.
      if (hidden) {
        layer([&](int o, const Vec& c) SN_INLINE_LAMBDA { z[o] = act<H>(c, S.hp); });
        continue;
      }
    }
    layer([&](int o, const Vec& c) SN_INLINE_LAMBDA { z[o] = c; });
    if (hidden) {
      if (H == kAnyHidden && S.hidden == kTranslated) {
        translated<Mode>(*S.hf, *S.hb, S.hp, z, S.out[l], kTrain ? V.dz(l + 1) : nullptr);
      } else if (kTrain && !hidden_from_output<H>(S)) {
        Vec* g = V.dz(l + 1);
        for (int o = 0; o < S.out[l]; ++o) hidden_both<H>(S, z[o], z[o], g[o]);
      } else {
        for (int o = 0; o < S.out[l]; ++o) z[o] = hidden_act<H>(S, z[o]);
      }
    } else if (S.output == kTranslated) {
      translated<Mode>(*S.of, *S.ob, S.op, z, S.out[l], kTrain ? V.dz(l + 1) : nullptr);
    } else if (kTrain && S.output != int(Builtin::linear)) {
      Vec* g = V.dz(l + 1);
      for (int o = 0; o < S.out[l]; ++o) act_both_any(S.output, z[o], S.op, z[o], g[o]);
    } else if (S.output != int(Builtin::linear)) {
      for (int o = 0; o < S.out[l]; ++o) z[o] = act_any(S.output, z[o], S.op);
    }
  }
}

// f'(z) of unit vector i of hidden width block l, after a training forward pass.
template <int H, class Mode>
SN_INLINE typename Mode::V hidden_grad(const View<Mode>& V, int l, int i) {
  if constexpr (H == kAnyHidden) {
    if (hidden_from_output<H>(V.S)) return act_grad_a_any(V.S.hidden, V.act(l)[i], V.S.hp);
  } else if constexpr (kFromOutput<H>) {
    return act_grad_a<H>(V.act(l)[i], V.S.hp);
  }
  return V.dz(l)[i];
}

// The loss of nn/loss.h per lane (lv) and its derivative by the prediction (lg), for the error
// e (0 in dead lanes) and the target t.
struct LossArgs {
  LossKind kind;
  float delta;
  // A sample's squared error above it: exploded (per network of a pair).
  float sample_limit[2] = {std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity()};
};
// step_impl's verdicts (nn/trainer.h's order: a non-finite loss, then a sample above the limit,
// then a non-finite update), two bits per network.
enum StepVerdict : int { kStepOk = 0, kStepNonfinite = 1, kStepExploded = 2 };
template <class Vec>
SN_INLINE void loss_both(const LossArgs& L, const Vec& e, const Vec& t, Vec& lv, Vec& lg) {
  switch (L.kind) {
    case LossKind::l1:
      lv = select(e < 0.0f, -e, e);
      lg = select(e > 0.0f, splat<Vec>(1.0f), select(e < 0.0f, splat<Vec>(-1.0f), splat<Vec>(0.0f)));
      break;
    case LossKind::relative_l2: {
      const Vec inv = 1.0f / (t * t + float(kRelativeL2Eps));
      lv = e * e * inv;
      lg = 2.0f * e * inv;
      break;
    }
    case LossKind::huber: {
      const Vec a = select(e < 0.0f, -e, e), d = splat<Vec>(L.delta);
      lv = select(a <= d, 0.5f * e * e, d * (a - 0.5f * d));  // NaN takes the second: stays NaN
      lg = select(e > d, d, select(e < -d, -d, e));
      break;
    }
    default:
      lv = e * e;
      lg = 2.0f * e;
  }
}

// The lanes of the first n samples (of each network).
template <class Mode>
SN_INLINE mask_of<typename Mode::V> lane_mask(int n) {
  mask_of<typename Mode::V> lanes;
  for (int i = 0; i < kLanesOf<Mode>; ++i) lanes[i] = i;
  return lanes < n * Mode::kPar;
}

template <class Isa, class Mode, int H>
SN_INLINE int step_impl(const View<Mode>& V, const float* const mb[], int batch,
                        const AdamStep& c, const LossArgs& lf, double* loss_out) {
  using Vec = typename Mode::V;
  using E = typename Mode::E;
  static_assert(Mode::kSamples == 8, "training runs 8 samples (of each network) per block");
  constexpr int k = Mode::kPar, B = Mode::kSamples;
  const Layout& S = V.S;
  const float* p = V.p();
  // The gradient is stored by the minibatch's first block and added to by the others: the
  // floats no block writes (padding) stay 0 from the arena's start.
  float* g = V.g();
  const int outputs = S.out[S.L - 1];
  const float scale = 2.0f / float(batch * outputs);  // l2's: d mean(e^2) / d y'
  const float mean = 1.0f / float(batch * outputs);
  // Each sample's loss (its outputs' sum) in float, the minibatch's sum in double, as the gl
  // kernel does: a step is refused by the same rule on both (nn/trainer.h).
  double loss_sum[k] = {};
  bool finite[k], too_big[k];
  for (int h = 0; h < k; ++h) finite[h] = true, too_big[h] = false;
  for (int first = 0; first < batch; first += B) {
    const int n = batch - first < B ? batch - first : B;
    Vec sq = splat<Vec>(0.0f), se = splat<Vec>(0.0f);
    load_block<Mode>(V, mb, first / B);
    forward_block<H, Mode, true>(V);
    // Output error: d = dloss/dy' * act'(y').
    const auto mask = lane_mask<Mode>(n);
    Vec* d = V.d(0);
    const Vec* yhat = V.act(S.L);
    for (int o = 0; o < outputs; ++o) {
      const Vec t = V.t()[o];
      Vec diff = yhat[o] - t;
      diff = mask ? diff : splat<Vec>(0.0f);
      Vec gr;
      if (lf.kind == LossKind::l2) {
        sq += diff * diff;
        gr = scale * diff;
      } else {
        Vec lv, lg;
        loss_both(lf, diff, t, lv, lg);
        sq += lv;
        se += diff * diff;
        gr = mean * lg;
      }
      d[o] = S.output == int(Builtin::linear) ? gr : gr * V.dz(S.L)[o];
    }
    if (lf.kind == LossKind::l2) se = sq;
    for (int s = 0; s < n; ++s)
      for (int h = 0; h < k; ++h) {
        finite[h] = finite[h] && std::isfinite(sq[s * k + h]);
        too_big[h] = too_big[h] || se[s * k + h] > lf.sample_limit[h];
        loss_sum[h] += double(sq[s * k + h]);
      }
    int cur = 0;
    for (int l = S.L - 1; l >= 0; --l) {
      const int in = S.in[l], out = S.out[l], inpad = S.inpad[l], tpad = S.tpad[l];
      Vec* dl = V.d(cur);
      // Transposed activations for the outer-product gradient (pad columns stay 0), and the
      // bias gradient: each unit's errors summed over the samples, eight units at a time as
      // sums of transposed rows (hsum_double's order).
      const Vec* a = V.act(l);
      float* aT = V.at(l);
      for (int c = 0; c < tpad; c += 8) {
        E r[8];
        for (int q = 0; q < 8; ++q) r[q] = c + q < in ? (E)a[c + q] : E{};
        transpose8(r);
        for (int s = 0; s < B; ++s) *reinterpret_cast<E*>(aT + (std::size_t(s) * tpad + c) * k) = r[s];
      }
      float* gb = g + S.boff[l] * k;
      for (int c = 0; c < out; c += 8) {
        E r[8];
        for (int q = 0; q < 8; ++q) r[q] = c + q < out ? (E)dl[c + q] : E{};
        transpose8(r);
        Vec u[8];  // the sums are of floats, whatever the units
        for (int q = 0; q < 8; ++q) u[q] = (Vec)r[q];
        const Vec sum = ((u[0] + u[4]) + (u[1] + u[5])) + ((u[2] + u[6]) + (u[3] + u[7]));
        Vec& to = *reinterpret_cast<Vec*>(gb + c * k);
        to = first == 0 ? sum : to + sum;
      }
      const float* dlf = reinterpret_cast<const float*>(dl);
      if (first == 0) {
        in_groups<GradientFirst, Mode>(out, g + S.woff[l] * k, inpad, tpad, dlf, aT);
        gradient_tail<Mode, false>(out, g + S.woff[l] * k, inpad, tpad, dlf, aT);
      } else {
        in_groups<Gradient, Mode>(out, g + S.woff[l] * k, inpad, tpad, dlf, aT);
        gradient_tail<Mode, true>(out, g + S.woff[l] * k, inpad, tpad, dlf, aT);
      }
      if (l == 0) break;
      Vec* prev = V.d(cur ^ 1);
      in_groups<Backward, Mode>(in, p + S.woff[l] * k, inpad, out, dl, prev,
                                [&](int i) SN_INLINE_LAMBDA { return hidden_grad<H>(V, l, i); });
      cur ^= 1;
    }
  }
  int verdict = 0;
  bool any = false;
  for (int h = 0; h < k; ++h) {
    loss_out[h] = loss_sum[h] / (double(batch) * outputs);
    const int v = !finite[h] || !std::isfinite(loss_out[h]) ? kStepNonfinite : too_big[h] ? kStepExploded : kStepOk;
    verdict |= v << (2 * h);
    any = any || v == kStepOk;
  }
  if (!any) return verdict;
  // Adam into the other parameter copy; the current one survives a non-finite result. Every
  // float is updated alike, so the widest vectors serve (P is a multiple of 16).
  using A = std::conditional_t<std::is_same_v<Isa, Avx512>, v16, v8>;
  constexpr int al = int(sizeof(A) / sizeof(float));
  const A b1 = splat<A>(c.beta1), b2 = splat<A>(c.beta2), ob1 = splat<A>(1.0f - c.beta1), ob2 = splat<A>(1.0f - c.beta2);
  const A lr = splat<A>(c.lr * c.inv_c1), ic2 = splat<A>(c.inv_c2), eps = splat<A>(c.eps);
  A* __restrict pn = reinterpret_cast<A*>(V.pnext());
  const A* __restrict pc = reinterpret_cast<const A*>(p);
  A* __restrict m = reinterpret_cast<A*>(V.m());
  A* __restrict v = reinterpret_cast<A*>(V.v());
  const A* __restrict gv = reinterpret_cast<const A*>(g);
  A bad = splat<A>(0.0f);  // w - w is 0 for finite w, NaN otherwise
  for (std::size_t j = 0; j < S.P * k / al; ++j) {
    const A gj = gv[j];
    const A mj = b1 * m[j] + ob1 * gj;
    const A vj = b2 * v[j] + ob2 * gj * gj;
    m[j] = mj;
    v[j] = vj;
    const A w = pc[j] - lr * mj / (vsqrt<Isa>(vj * ic2) + eps);
    bad += w - w;
    pn[j] = w;
  }
  for (int i = 0; i < al; ++i)  // lane i holds parameters of network i % k
    if (bad[i] != 0.0f && ((verdict >> (2 * (i % k))) & 3) == kStepOk) verdict |= kStepNonfinite << (2 * (i % k));
  return verdict;
}

template <int H, class Mode>
SN_INLINE double loss_impl(const View<Mode>& V, const float* x, const float* y, std::size_t count, const LossArgs& lf) {
  using Vec = typename Mode::V;
  const Layout& S = V.S;
  const int outputs = S.out[S.L - 1];
  double sum = 0;
  for (std::size_t first = 0; first < count; first += Mode::kSamples) {
    const int n = count - first < std::size_t(Mode::kSamples) ? int(count - first) : Mode::kSamples;
    gather_inputs<Mode>(V, x, first, n);
    gather_targets<Mode>(V, y, first, n);
    forward_block<H, Mode>(V);
    const auto mask = lane_mask<Mode>(n);
    const Vec* yhat = V.act(S.L);
    Vec sq = splat<Vec>(0.0f);
    for (int o = 0; o < outputs; ++o) {
      const Vec t = V.t()[o];
      Vec diff = yhat[o] - t;
      diff = mask ? diff : splat<Vec>(0.0f);
      Vec lv, lg;
      loss_both(lf, diff, t, lv, lg);
      sq += lv;
    }
    if constexpr (kLanesOf<Mode> == 16) {  // two blocks of 8, summed as 8-lane kernels sum them
      sum += hsum_double(v8(__builtin_shufflevector(sq, sq, 0, 1, 2, 3, 4, 5, 6, 7)));
      sum += hsum_double(v8(__builtin_shufflevector(sq, sq, 8, 9, 10, 11, 12, 13, 14, 15)));
    } else {
      sum += hsum_double(sq);
    }
  }
  return count ? sum / (double(count) * outputs) : 0.0;
}

template <int H, class Mode>
SN_INLINE void forward_impl(const View<Mode>& V, const float* x, std::size_t count, float* out) {
  const Layout& S = V.S;
  const int outputs = S.out[S.L - 1];
  constexpr int B = Mode::kSamples;
  for (std::size_t first = 0; first < count; first += B) {
    const int n = count - first < std::size_t(B) ? int(count - first) : B;
    gather_inputs<Mode>(V, x, first, n);
    forward_block<H, Mode>(V);
    const float* yhat = reinterpret_cast<const float*>(V.act(S.L));
    for (int s = 0; s < n; ++s)
      for (int o = 0; o < outputs; ++o) out[(first + s) * outputs + o] = yhat[o * B + s];
  }
}

// The renderer's blocks of 8 samples (CpuNet::forward_lanes), Mode::kSamples / 8 blocks at a time.
template <int H, class Mode>
SN_INLINE void lanes_impl(const Arena& A, const float* x, std::size_t blocks, float* y) {
  constexpr std::size_t per = Mode::kSamples / 8, bytes = 8 * sizeof(float);
  const View<Mode> V(A);
  const Layout& S = V.S;
  const std::size_t in = std::size_t(S.in[0]), out = std::size_t(S.out[S.L - 1]);
  std::size_t b = 0;
  for (; b + per <= blocks; b += per) {
    float* a0 = reinterpret_cast<float*>(V.act(0));
    for (std::size_t i = 0; i < in; ++i)
      for (std::size_t q = 0; q < per; ++q) std::memcpy(a0 + (i * per + q) * 8, x + ((b + q) * in + i) * 8, bytes);
    forward_block<H, Mode>(V);
    const float* yo = reinterpret_cast<const float*>(V.act(S.L));
    for (std::size_t o = 0; o < out; ++o)
      for (std::size_t q = 0; q < per; ++q) std::memcpy(y + ((b + q) * out + o) * 8, yo + (o * per + q) * 8, bytes);
  }
  if constexpr (per > 1)
    if (b < blocks) lanes_impl<H, OneAvx>(A, x + b * in * 8, blocks - b, y + b * out * 8);  // only Wide has per > 1
}

template <int H, class Mode>
SN_INLINE void counts_impl(const View<Mode>& V, const float* x, std::size_t count,
                           std::vector<std::vector<uint32_t>>& counts) {
  using Vec = typename Mode::V;
  using Mask = mask_of<Vec>;
  constexpr int lanes = kLanesOf<Mode>;
  const Layout& S = V.S;
  std::size_t units = 0;
  for (int l = 1; l < S.L; ++l) units += std::size_t(S.in[l]);
  // Per unit and lane: -(number of samples that hit). Plain ints moved with memcpy: heap
  // memory from std::vector is only 16-byte aligned, and GCC stores vectors with aligned moves.
  std::vector<int32_t> hits(units * lanes, 0);
  for (std::size_t first = 0; first < count; first += Mode::kSamples) {
    const int n = count - first < std::size_t(Mode::kSamples) ? int(count - first) : Mode::kSamples;
    gather_inputs<Mode>(V, x, first, n);
    forward_block<H, Mode, true>(V);
    const Mask valid = lane_mask<Mode>(n);
    std::size_t u = 0;
    for (int l = 1; l < S.L; ++l) {
      const Vec* a = V.act(l);
      for (int i = 0; i < S.in[l]; ++i, ++u) {
        Mask hit;
        const int kind = H == kAnyHidden ? S.hidden : H;
        if (kind == int(Builtin::tanh)) hit = (a[i] > 0.99f) | (a[i] < -0.99f);
        else if (kind == int(Builtin::sigmoid)) hit = (a[i] < 0.01f) | (a[i] > 0.99f);
        else if (kind == int(Builtin::relu) || kind == int(Builtin::leaky_relu)) hit = a[i] > 0.0f;
        else {
          const Vec g = hidden_grad<H>(V, l, i);
          hit = (g < 0.01f) & (g > -0.01f);  // flat: the unit passes (almost) no gradient
        }
        Mask h;
        std::memcpy(&h, &hits[u * lanes], sizeof h);
        h += hit & valid;  // comparisons give -1 per true lane
        std::memcpy(&hits[u * lanes], &h, sizeof h);
      }
    }
  }
  counts.assign(std::size_t(S.L - 1), {});
  std::size_t u = 0;
  for (int l = 1; l < S.L; ++l)
    for (int i = 0; i < S.in[l]; ++i, ++u) {
      int64_t total = 0;
      for (int s = 0; s < lanes; ++s) total -= hits[u * lanes + s];
      counts[l - 1].push_back(uint32_t(total));
    }
}

template <int K, class Vec>
SN_INLINE void activation_impl(float p, const float* z, std::size_t n, float* f, float* df) {
  constexpr std::size_t lanes = sizeof(Vec) / sizeof(float);
  for (std::size_t i = 0; i < n; i += lanes) {
    Vec zv = splat<Vec>(0.0f);
    for (std::size_t k = 0; k < lanes && i + k < n; ++k) zv[k] = z[i + k];
    Vec a, g;
    act_both<K>(zv, p, a, g);
    const Vec a_only = act<K>(zv, p);
    if constexpr (kFromOutput<K>) g = act_grad_a<K>(a_only, p);
    for (std::size_t k = 0; k < lanes && i + k < n; ++k) f[i + k] = a_only[k], df[i + k] = g[k];
  }
}

// The entry points per instruction set; everything above inlines into them. One set per
// kernel: ISA (the tag), ATTR (the function target), WIDE (the inference mode), VEC (the
// activation test's vectors).
using StepFn = int (*)(const Arena&, const float* const*, int, const AdamStep&, const LossArgs&, double*);
using LossFn = double (*)(const Arena&, const float*, const float*, std::size_t, const LossArgs&);
using ForwardFn = void (*)(const Arena&, const float*, std::size_t, float*);
using CountsFn = void (*)(const Arena&, const float*, std::size_t, std::vector<std::vector<uint32_t>>&);
using LanesFn = void (*)(const Arena&, const float*, std::size_t, float*);
using ActivationFn = void (*)(float, const float*, std::size_t, float*, float*);

// The kernels flush denormal floats to zero (MXCSR's FTZ and DAZ), as GPUs do: a relu network's
// dead units let Adam's moments decay into denormals, which cost the CPU a slow path on every
// operation (8x8 relu trained at 16M sample-steps/s per core instead of 20M). The caller's
// MXCSR is restored on return.
struct FlushDenormals {
  unsigned saved = _mm_getcsr();
  FlushDenormals() { _mm_setcsr(saved | 0x8040); }
  ~FlushDenormals() { _mm_setcsr(saved); }
};

#define SN_KERNEL_SET(NAME, ISA, ATTR, ONE, WIDE, VEC)                                                              \
  template <int H>                                                                                                  \
  ATTR int step_##NAME(const Arena& A, const float* const* mb, int batch, const AdamStep& c, const LossArgs& lf,     \
                       double* l) {                                                                                 \
    FlushDenormals ftz;                                                                                             \
    return step_impl<ISA, ONE, H>(View<ONE>(A), mb, batch, c, lf, l);                                               \
  }                                                                                                                 \
  template <int H>                                                                                                  \
  ATTR double loss_##NAME(const Arena& A, const float* x, const float* y, std::size_t n, const LossArgs& lf) {      \
    FlushDenormals ftz;                                                                                             \
    return loss_impl<H>(View<ONE>(A), x, y, n, lf);                                                                 \
  }                                                                                                                 \
  template <int H>                                                                                                  \
  ATTR void forward_##NAME(const Arena& A, const float* x, std::size_t n, float* out) {                             \
    FlushDenormals ftz;                                                                                             \
    forward_impl<H>(View<ONE>(A), x, n, out);                                                                       \
  }                                                                                                                 \
  template <int H>                                                                                                  \
  ATTR void lanes_##NAME(const Arena& A, const float* x, std::size_t n, float* y) {                                 \
    FlushDenormals ftz;                                                                                             \
    lanes_impl<H, WIDE>(A, x, n, y);                                                                                \
  }                                                                                                                 \
  template <int H>                                                                                                  \
  ATTR void counts_##NAME(const Arena& A, const float* x, std::size_t n, std::vector<std::vector<uint32_t>>& c) {   \
    FlushDenormals ftz;                                                                                             \
    counts_impl<H>(View<ONE>(A), x, n, c);                                                                          \
  }                                                                                                                 \
  template <int K>                                                                                                  \
  ATTR void activation_##NAME(float p, const float* z, std::size_t n, float* f, float* df) {                        \
    FlushDenormals ftz;                                                                                             \
    activation_impl<K, VEC>(p, z, n, f, df);                                                                        \
  }

#define SN_NO_TARGET
SN_KERNEL_SET(sse2, Sse2, SN_NO_TARGET, One, One, v8)
SN_KERNEL_SET(avx2, Avx2, __attribute__((target("avx2,fma"))), OneAvx, OneAvx, v8)
SN_KERNEL_SET(avx512, Avx512, SN_AVX512, OneAvx, Wide, v16)

// Validation with 16 samples per register (AVX-512 only).
template <int H>
SN_AVX512 double loss_wide(const Arena& A, const float* x, const float* y, std::size_t n, const LossArgs& lf) {
  FlushDenormals ftz;
  return loss_impl<H>(View<Wide>(A), x, y, n, lf);
}

// Two networks in lock-step (AVX-512 only).
template <int H>
SN_AVX512 int step_pair(const Arena& A, const float* const* mb, int batch, const AdamStep& c, const LossArgs& lf,
                        double* l) {
  FlushDenormals ftz;
  return step_impl<Avx512, Pair, H>(View<Pair>(A), mb, batch, c, lf, l);
}

enum class Kernel : int { sse2, avx2, avx512 };
const char* const kKernelNames[] = {"sse2", "avx2", "avx512"};

struct Kernels {
  StepFn step;
  LossFn loss;
  ForwardFn forward;
  CountsFn counts;
  LanesFn lanes;
  StepFn pair;  // null where the kernel has no pair mode
};

template <int H>
Kernels kernels_for(Kernel k) {
  if (k == Kernel::avx512)
    // Validation runs 16 samples per register; rows through forward() and unit counts are
    // avx2's 8-lane code: compiled again with AVX-512 encodings it bought nothing
    // (docs/performance.md), and each instantiation costs compile time.
    return {step_avx512<H>, loss_wide<H>, forward_avx2<H>, counts_avx2<H>, lanes_avx512<H>, step_pair<H>};
  if (k == Kernel::avx2) return {step_avx2<H>, loss_avx2<H>, forward_avx2<H>, counts_avx2<H>, lanes_avx2<H>, nullptr};
  return {step_sse2<H>, loss_sse2<H>, forward_sse2<H>, counts_sse2<H>, lanes_sse2<H>, nullptr};
}

bool cpu_has(Kernel k) {
  __builtin_cpu_init();
  switch (k) {
    case Kernel::avx512:
      return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
             __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512bw") && cpu_has(Kernel::avx2);
    case Kernel::avx2: return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    default: return true;
  }
}

Kernel kernel_named(const std::string& name) {
  for (int i = 0; i < 3; ++i)
    if (name == kKernelNames[i]) return Kernel(i);
  throw std::invalid_argument("unknown cpu kernel '" + name + "' (valid: avx512, avx2, sse2)");
}

// The kernel in use: the widest the CPU has, or SHADENET_CPU_KERNEL's when the CPU has that.
std::atomic<int>& kernel_flag() {
  static std::atomic<int> flag = [] {
    if (const char* force = std::getenv("SHADENET_CPU_KERNEL"); force && *force) {
      const Kernel k = kernel_named(force);
      if (!cpu_has(k)) throw std::runtime_error(std::string("SHADENET_CPU_KERNEL=") + force + ": this CPU lacks it");
      return int(k);
    }
    return int(cpu_has(Kernel::avx512) ? Kernel::avx512 : cpu_has(Kernel::avx2) ? Kernel::avx2 : Kernel::sse2);
  }();
  return flag;
}
Kernel kernel_in_use() { return Kernel(kernel_flag().load(std::memory_order_relaxed)); }

Kernels kernels(int hidden) {
  const Kernel kind = kernel_in_use();
  return hidden == int(Builtin::tanh) ? kernels_for<int(Builtin::tanh)>(kind) : kernels_for<kAnyHidden>(kind);
}

}  // namespace

bool has_cpu_code(const MlpSpec& spec, Activation* without) {
  for (Activation a : {spec.activation, spec.output_activation})
    if (!activation_has_cpu_code(a)) {
      if (without) *without = a;
      return false;
    }
  return true;
}

void cpu_translated(const ActivationExpr& e, float param, const float* z, std::size_t n, float* out, float* grad) {
  // The runners read whole vectors, aligned: z copied into vectors of 16, the last one padded.
  struct alignas(64) Block {
    float f[16];
  };
  std::vector<Block> in((n + 15) / 16), res(in.size()), res_grad(grad ? in.size() : 0);
  std::memcpy(in.data(), z, n * sizeof(float));
  const Kernel k = kernel_in_use();
  const ExprFn run = k == Kernel::avx512 ? expr_avx512 : k == Kernel::avx2 ? expr_avx2 : expr_sse2;
  {
    FlushDenormals ftz;
    run(e, param, in.data()->f, in.size() * 16, res.data()->f, grad ? res_grad.data()->f : nullptr);
  }
  std::memcpy(out, res.data(), n * sizeof(float));
  if (grad) std::memcpy(grad, res_grad.data(), n * sizeof(float));
}

void cpu_activation(Activation a, float param, const float* z, std::size_t n, float* f, float* df) {
  const ActivationDef& d = activation_def(a);
  if (!activation_has_cpu_code(a)) throw std::invalid_argument(activation_without_cpu_code(a));
  if (d.simd < 0) return cpu_translated(*d.cpu_both, param, z, n, f, df);
  const int kind = d.simd;
  const Kernel k = kernel_in_use();
  with_builtin(kind, [&](auto kk) {
    constexpr int K = decltype(kk)::value;
    const ActivationFn fn = k == Kernel::avx512 ? activation_avx512<K> : k == Kernel::avx2 ? activation_avx2<K> : activation_sse2<K>;
    fn(param, z, n, f, df);
  });
}

AdamStep AdamStep::at(const TrainConfig& cfg, long long t) {
  AdamStep s;
  s.lr = float(cfg.lr);
  s.beta1 = float(cfg.beta1);
  s.beta2 = float(cfg.beta2);
  s.eps = float(cfg.eps);
  s.inv_c1 = float(1.0 / (1.0 - std::pow(cfg.beta1, double(t))));
  s.inv_c2 = float(1.0 / (1.0 - std::pow(cfg.beta2, double(t))));
  return s;
}

const char* cpu_kernel_name() { return kKernelNames[int(kernel_in_use())]; }

std::vector<std::string> cpu_kernels_available() {
  std::vector<std::string> names;
  for (int i = 0; i < 3; ++i)
    if (cpu_has(Kernel(i))) names.push_back(kKernelNames[i]);
  return names;
}

void use_cpu_kernel(const std::string& name) {
  const Kernel k = kernel_named(name);
  if (!cpu_has(k)) throw std::runtime_error("this CPU has no " + name + " (it has: " + [] {
                     std::string s;
                     for (const auto& n : cpu_kernels_available()) s += (s.empty() ? "" : ", ") + n;
                     return s;
                   }() + ")");
  kernel_flag() = int(k);
}

std::size_t minibatch_floats(int batch, int inputs, int outputs) {
  return std::size_t((batch + 7) / 8) * std::size_t(inputs + outputs) * 8;
}

void pack_minibatch(const float* x, const float* y, int inputs, int outputs, const uint32_t* rows, int batch,
                    float* mb) {
  for (int first = 0; first < batch; first += 8, mb += std::size_t(inputs + outputs) * 8) {
    const int n = std::min(8, batch - first);
    for (int s = 0; s < 8; ++s) {
      const float* xr = s < n ? x + std::size_t(rows[first + s]) * inputs : nullptr;
      const float* yr = s < n ? y + std::size_t(rows[first + s]) * outputs : nullptr;
      for (int i = 0; i < inputs; ++i) mb[i * 8 + s] = xr ? xr[i] : 0.0f;
      for (int o = 0; o < outputs; ++o) mb[(inputs + o) * 8 + s] = yr ? yr[o] : 0.0f;
    }
  }
}

CpuNet::CpuNet(const MlpSpec& spec, const float* params) : spec_(spec), layout_(std::make_unique<Layout>(spec)) {
  const std::size_t bytes = (layout_->params(1) + layout_->scratch) * sizeof(float);
  arena_ = static_cast<float*>(std::aligned_alloc(64, bytes));
  if (!arena_) throw std::bad_alloc();
  std::memset(arena_, 0, bytes);
  set_params(params);
}

CpuNet::~CpuNet() { std::free(arena_); }

namespace {
// Parameters between the shared flat layout and network h of a padded copy (kPar = k networks
// interleaved). Pad floats are left alone (0 from the arena's start: Adam keeps them 0).
void pack(const MlpSpec& spec, const Layout& S, const float* flat, float* p, int k = 1, int h = 0) {
  for (int l = 0; l < S.L; ++l) {
    const float* w = flat + spec.weight_offset(l);
    for (int o = 0; o < S.out[l]; ++o)
      for (int i = 0; i < S.in[l]; ++i) p[(S.woff[l] + std::size_t(o) * S.inpad[l] + i) * k + h] = w[o * S.in[l] + i];
    for (int o = 0; o < S.out[l]; ++o) p[(S.boff[l] + o) * k + h] = flat[spec.bias_offset(l) + o];
  }
}
void unpack(const MlpSpec& spec, const Layout& S, const float* p, float* flat, int k = 1, int h = 0) {
  for (int l = 0; l < S.L; ++l) {
    float* w = flat + spec.weight_offset(l);
    for (int o = 0; o < S.out[l]; ++o)
      for (int i = 0; i < S.in[l]; ++i) w[o * S.in[l] + i] = p[(S.woff[l] + std::size_t(o) * S.inpad[l] + i) * k + h];
    for (int o = 0; o < S.out[l]; ++o) flat[spec.bias_offset(l) + o] = p[(S.boff[l] + o) * k + h];
  }
}
// Copies `count` floats of network `from_h` of a k-network array into network `to_h` of a
// j-network array (a pair's arrays to one network's and back).
void restride(const float* from, int k, int from_h, float* to, int j, int to_h, std::size_t count) {
  for (std::size_t i = 0; i < count; ++i) to[i * j + to_h] = from[i * k + from_h];
}
}  // namespace

void CpuNet::set_params(const float* flat) {
  const Layout& S = *layout_;
  float* p = arena_ + S.P * cur_;
  std::memset(p, 0, S.P * sizeof(float));
  pack(spec_, S, flat, p);
  // The other copy's pad columns must be 0 too: Adam writes every float of it.
  std::memcpy(arena_ + S.P * (cur_ ^ 1), p, S.P * sizeof(float));
  std::memset(arena_ + 2 * S.P, 0, 2 * S.P * sizeof(float));
}

void CpuNet::get_params(float* flat) const { unpack(spec_, *layout_, arena_ + layout_->P * cur_, flat); }

void CpuNet::get_gradient(float* flat) const { unpack(spec_, *layout_, arena_ + 4 * layout_->P, flat); }

namespace {
Arena whole(const Layout& S, float* arena, int cur) { return {S, arena, arena + S.params(1), cur}; }
// A network's verdict bits (step_impl) as CpuNet::step's answer.
bool applied(int verdict, DivergenceKind* why) {
  if (verdict == kStepOk) return true;
  if (why) *why = verdict == kStepExploded ? DivergenceKind::exploded : DivergenceKind::nonfinite;
  return false;
}
}  // namespace

bool CpuNet::step(const float* mb, int batch, const AdamStep& adam, double* loss, DivergenceKind* why) {
  LossArgs lf{loss_.kind, float(loss_.delta)};
  lf.sample_limit[0] = sample_limit_;
  const float* one[1] = {mb};
  if (!applied(kernels(layout_->hidden).step(whole(*layout_, arena_, cur_), one, batch, adam, lf, loss), why))
    return false;
  cur_ ^= 1;
  return true;
}

double CpuNet::mse(const float* x, const float* y, std::size_t count) {
  return kernels(layout_->hidden).loss(whole(*layout_, arena_, cur_), x, y, count, LossArgs{LossKind::l2, 1.0f});
}

double CpuNet::mean_loss(const float* x, const float* y, std::size_t count) {
  return kernels(layout_->hidden).loss(whole(*layout_, arena_, cur_), x, y, count, LossArgs{loss_.kind, float(loss_.delta)});
}

void CpuNet::forward(const float* x, std::size_t count, float* out) { kernels(layout_->hidden).forward(whole(*layout_, arena_, cur_), x, count, out); }

void CpuNet::forward_lanes(const float* x, std::size_t blocks, float* y) {
  kernels(layout_->hidden).lanes(whole(*layout_, arena_, cur_), x, blocks, y);
}

std::vector<std::vector<uint32_t>> CpuNet::unit_counts(const float* x, std::size_t count) {
  std::vector<std::vector<uint32_t>> counts;
  kernels(layout_->hidden).counts(whole(*layout_, arena_, cur_), x, count, counts);
  return counts;
}

bool CpuNetPair::available() { return kernel_in_use() == Kernel::avx512; }

bool CpuNetPair::can_pair(const CpuNet& a, const CpuNet& b) {
  return a.spec_.same_shape(b.spec_) && a.loss_ == b.loss_;
}

CpuNetPair::CpuNetPair(const CpuNet& a, const CpuNet& b) : layout_(std::make_unique<Layout>(a.spec_)) {
  if (!available()) throw std::logic_error("CpuNetPair: the " + std::string(cpu_kernel_name()) + " kernel has no pair mode");
  if (!can_pair(a, b)) throw std::invalid_argument("CpuNetPair: the two networks differ in architecture or loss");
  const Layout& S = *layout_;
  const std::size_t bytes = (S.params(2) + S.scratch) * sizeof(float);
  arena_ = static_cast<float*>(std::aligned_alloc(64, bytes));
  if (!arena_) throw std::bad_alloc();
  std::memset(arena_, 0, bytes);
  const CpuNet* nets[2] = {&a, &b};
  for (int h = 0; h < 2; ++h) {
    const CpuNet& n = *nets[h];
    // This pair's copy 0 is each network's current one; m and v follow.
    restride(n.arena_ + S.P * n.cur_, 1, 0, arena_, 2, h, S.P);
    restride(n.arena_ + S.P * (n.cur_ ^ 1), 1, 0, arena_ + 2 * S.P, 2, h, S.P);
    restride(n.arena_ + 2 * S.P, 1, 0, arena_ + 4 * S.P, 2, h, 2 * S.P);
    limits_[h] = n.sample_limit_;
  }
  loss_ = a.loss_;
}

CpuNetPair::~CpuNetPair() { std::free(arena_); }

bool CpuNetPair::step(const float* const mb[2], int batch, const AdamStep& adam,
                      double loss[2], bool ok[2], DivergenceKind why[2]) {
  LossArgs lf{loss_.kind, float(loss_.delta)};
  lf.sample_limit[0] = limits_[0];
  lf.sample_limit[1] = limits_[1];
  const Arena A{*layout_, arena_, arena_ + layout_->params(2), cur_};
  const int verdict = kernels(layout_->hidden).pair(A, mb, batch, adam, lf, loss);
  for (int h = 0; h < 2; ++h) ok[h] = applied((verdict >> (2 * h)) & 3, &why[h]);
  if (!ok[0] || !ok[1]) return false;
  cur_ ^= 1;
  return true;
}

void CpuNetPair::get(int h, CpuNet& net, bool written) const {
  const Layout& S = *layout_;
  const int c = written ? cur_ ^ 1 : cur_;
  float* p = net.arena_ + S.P * net.cur_;
  restride(arena_ + 2 * S.P * c, 2, h, p, 1, 0, S.P);
  std::memcpy(net.arena_ + S.P * (net.cur_ ^ 1), p, S.P * sizeof(float));
  restride(arena_ + 4 * S.P, 2, h, net.arena_ + 2 * S.P, 1, 0, 3 * S.P);  // m, v, the gradient
}

}  // namespace sn::nn

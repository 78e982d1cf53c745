// The 32-byte vectors below never cross a non-inlined call, so GCC's ABI note does not apply;
// GCC 12 reports the register accumulators of rows_forward as maybe-uninitialized once splat's
// shuffle is inlined (every element is assigned before use: a false positive).
#pragma GCC diagnostic ignored "-Wpsabi"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

#include "nn/cpu_net.h"

#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <cstdlib>
#include <cstring>
#include <new>

#include "nn/cpu_activation.h"

namespace sn::nn {

namespace {

using namespace simd;

constexpr int kLanes = CpuNet::kLanes;
std::size_t round8(std::size_t n) { return (n + 7) & ~std::size_t(7); }
std::size_t round16(std::size_t n) { return (n + 15) & ~std::size_t(15); }

SN_INLINE float hsum(const v8& v) { return ((v[0] + v[4]) + (v[1] + v[5])) + ((v[2] + v[6]) + (v[3] + v[7])); }

}  // namespace

// Padded offsets, all in floats from the arena start and multiples of 16 (64 bytes).
// Parameters: layer l = rows [out][inpad] (inpad = in rounded up to 8, pad columns stay 0),
// then biases [round8(out)].
struct CpuNet::Layout {
  int L = 0;
  int in[kMaxHidden + 1] = {}, out[kMaxHidden + 1] = {}, inpad[kMaxHidden + 1] = {};
  std::size_t woff[kMaxHidden + 1] = {}, boff[kMaxHidden + 1] = {};  // within a parameter copy
  std::size_t P = 0;  // floats per parameter copy
  std::size_t aoff[kMaxHidden + 2] = {};  // activations of layer l (width(l) x 8), from o_act
  std::size_t toff[kMaxHidden + 1] = {};  // transposed activations (8 x inpad), from o_at
  int maxw = 0;
  // o_dz: f'(z) of every unit, same offsets as the activations (stored by a training forward
  // pass for hidden kinds that need z, and for the output layer).
  std::size_t o_p[2] = {}, o_m = 0, o_v = 0, o_g = 0, o_act = 0, o_dz = 0, o_at = 0, o_d[2] = {}, total = 0;
  int hidden = int(Builtin::tanh), output = int(Builtin::linear);  // Builtin ids (SIMD code)
  float hp = 0, op = 0;  // their parameters

  explicit Layout(const MlpSpec& s) {
    L = s.layers();
    hidden = activation_def(s.activation).simd;
    output = activation_def(s.output_activation).simd;
    if (hidden < 0 || output < 0)
      throw std::invalid_argument("activation '" + std::string(activation_name(hidden < 0 ? s.activation : s.output_activation)) +
                                  "' has no cpu code: train it with backend = \"gl\"");
    hp = float(s.param(s.activation));
    op = float(s.param(s.output_activation));
    maxw = s.max_width();
    std::size_t at = 0, a = 0;
    for (int l = 0; l < L; ++l) {
      in[l] = s.width(l);
      out[l] = s.width(l + 1);
      inpad[l] = int(round8(in[l]));
      woff[l] = P;
      boff[l] = P + std::size_t(out[l]) * inpad[l];
      P = round16(boff[l] + round8(out[l]));
      toff[l] = at;
      at += round16(std::size_t(kLanes) * inpad[l]);
    }
    for (int l = 0; l <= L; ++l) {
      aoff[l] = a;
      a += round16(std::size_t(s.width(l)) * kLanes);
    }
    std::size_t d = round16(std::size_t(maxw) * kLanes);
    std::size_t o = 0;
    for (auto* f : {&o_p[0], &o_p[1], &o_m, &o_v, &o_g}) *f = o, o += P;
    o_act = o, o += a;
    o_dz = o, o += a;
    o_at = o, o += at;
    o_d[0] = o, o += d;
    o_d[1] = o, o += d;
    total = o;
  }
};

namespace {

using Layout = CpuNet::Layout;

// Where a kernel finds everything of one net.
struct View {
  const Layout& S;
  float* base;
  int cur;
  float* p() const { return base + S.o_p[cur]; }
  float* pnext() const { return base + S.o_p[cur ^ 1]; }
  v8* act(int l) const { return reinterpret_cast<v8*>(base + S.o_act + S.aoff[l]); }
  v8* dz(int l) const { return reinterpret_cast<v8*>(base + S.o_dz + S.aoff[l]); }
  float* at(int l) const { return base + S.o_at + S.toff[l]; }
  v8* d(int k) const { return reinterpret_cast<v8*>(base + S.o_d[k]); }
};

// z[j] = b[j] + sum_i W[j][i] a[i] for R rows at once (R independent FMA chains). The
// accumulators are named variables, not an array: GCC kept an array acc[R] in memory for R < 8
// (a store and a load around every FMA; 4x4 networks ran at half speed).
template <int R>
SN_INLINE void rows_forward(const float* W, int inpad, const float* b, int in, const v8* a, v8* z) {
  const v8 zero = splat(0.0f);
  v8 c0 = R > 0 ? splat(b[0]) : zero, c1 = R > 1 ? splat(b[1]) : zero, c2 = R > 2 ? splat(b[2]) : zero,
     c3 = R > 3 ? splat(b[3]) : zero, c4 = R > 4 ? splat(b[4]) : zero, c5 = R > 5 ? splat(b[5]) : zero,
     c6 = R > 6 ? splat(b[6]) : zero, c7 = R > 7 ? splat(b[7]) : zero;
  for (int i = 0; i < in; ++i) {
    const v8 ai = a[i];
    const float* w = W + i;
    if constexpr (R > 0) c0 += splat(w[0]) * ai;
    if constexpr (R > 1) c1 += splat(w[inpad]) * ai;
    if constexpr (R > 2) c2 += splat(w[2 * inpad]) * ai;
    if constexpr (R > 3) c3 += splat(w[3 * inpad]) * ai;
    if constexpr (R > 4) c4 += splat(w[4 * inpad]) * ai;
    if constexpr (R > 5) c5 += splat(w[5 * inpad]) * ai;
    if constexpr (R > 6) c6 += splat(w[6 * inpad]) * ai;
    if constexpr (R > 7) c7 += splat(w[7 * inpad]) * ai;
  }
  if constexpr (R > 0) z[0] = c0;
  if constexpr (R > 1) z[1] = c1;
  if constexpr (R > 2) z[2] = c2;
  if constexpr (R > 3) z[3] = c3;
  if constexpr (R > 4) z[4] = c4;
  if constexpr (R > 5) z[5] = c5;
  if constexpr (R > 6) z[6] = c6;
  if constexpr (R > 7) z[7] = c7;
}

// prev[j] = sum_o W[o][j] d[o] for R columns at once.
template <int R>
SN_INLINE void cols_backward(const float* W, int inpad, int out, const v8* d, v8* prev) {
  v8 acc[R];
  for (int j = 0; j < R; ++j) acc[j] = splat(0.0f);
  for (int o = 0; o < out; ++o) {
    const v8 dv = d[o];
    for (int j = 0; j < R; ++j) acc[j] += splat(W[o * inpad + j]) * dv;
  }
  for (int j = 0; j < R; ++j) prev[j] = acc[j];
}

// G[j][:] += sum_s d[j][s] * aT[s][:] for R rows: the weight gradient as outer products, with
// the minibatch (s) as the reduction and the inputs on the SIMD axis.
template <int R>
SN_INLINE void rows_gradient(float* G, int inpad, const float* d, const float* aT) {
  for (int k = 0; k < inpad; k += kLanes) {
    v8 acc[R];
    for (int j = 0; j < R; ++j) acc[j] = *reinterpret_cast<const v8*>(G + j * inpad + k);
    for (int s = 0; s < kLanes; ++s) {
      const v8 a = *reinterpret_cast<const v8*>(aT + s * inpad + k);
      for (int j = 0; j < R; ++j) acc[j] += splat(d[j * kLanes + s]) * a;
    }
    for (int j = 0; j < R; ++j) *reinterpret_cast<v8*>(G + j * inpad + k) = acc[j];
  }
}

// Runs F<R>(first, R) over [0, n) in groups of 8 and one remainder group.
template <template <int> class F, class... Args>
SN_INLINE void in_groups(int n, Args&&... args) {
  int j = 0;
  for (; j + 8 <= n; j += 8) F<8>::run(j, args...);
  switch (n - j) {
    case 7: F<7>::run(j, args...); break;
    case 6: F<6>::run(j, args...); break;
    case 5: F<5>::run(j, args...); break;
    case 4: F<4>::run(j, args...); break;
    case 3: F<3>::run(j, args...); break;
    case 2: F<2>::run(j, args...); break;
    case 1: F<1>::run(j, args...); break;
    default: break;
  }
}
template <int R>
struct Forward {
  static SN_INLINE void run(int o, const float* W, int inpad, const float* b, int in, const v8* a, v8* z) {
    rows_forward<R>(W + o * inpad, inpad, b + o, in, a, z + o);
  }
};
template <int R>
struct Backward {
  static SN_INLINE void run(int i, const float* W, int inpad, int out, const v8* d, v8* prev) {
    cols_backward<R>(W + i, inpad, out, d, prev + i);
  }
};
template <int R>
struct Gradient {
  static SN_INLINE void run(int o, float* G, int inpad, const float* d, const float* aT) {
    rows_gradient<R>(G + o * inpad, inpad, d + o * kLanes, aT);
  }
};

// Loads rows into layer 0's activations (input i of sample s at [i][s]); lanes >= n are 0.
SN_INLINE void gather_inputs(const View& V, const float* x, const uint32_t* rows, std::size_t first, int n) {
  const int inputs = V.S.in[0];
  float* a0 = reinterpret_cast<float*>(V.act(0));
  for (int s = 0; s < kLanes; ++s) {
    if (s < n) {
      const float* xr = x + std::size_t(rows ? rows[first + s] : first + s) * inputs;
      for (int i = 0; i < inputs; ++i) a0[i * kLanes + s] = xr[i];
    } else {
      for (int i = 0; i < inputs; ++i) a0[i * kLanes + s] = 0.0f;
    }
  }
}

// The forward pass; kTrain also stores f'(z) where backpropagation needs it: for hidden kinds
// whose derivative does not follow from a (sine, gelu, swish), and for a non-linear output layer.
template <int H, bool kTrain = false>
SN_INLINE void forward_block(const View& V) {
  const Layout& S = V.S;
  const float* p = V.p();
  for (int l = 0; l < S.L; ++l) {
    v8* z = V.act(l + 1);
    in_groups<Forward>(S.out[l], p + S.woff[l], S.inpad[l], p + S.boff[l], S.in[l], V.act(l), z);
    if (l + 1 < S.L) {
      if constexpr (kTrain && !kFromOutput<H>) {
        v8* g = V.dz(l + 1);
        for (int o = 0; o < S.out[l]; ++o) act_both<H>(z[o], S.hp, z[o], g[o]);
      } else {
        for (int o = 0; o < S.out[l]; ++o) z[o] = act<H>(z[o], S.hp);
      }
    } else if (kTrain && S.output != int(Builtin::linear)) {
      v8* g = V.dz(l + 1);
      for (int o = 0; o < S.out[l]; ++o) act_both_any(S.output, z[o], S.op, z[o], g[o]);
    } else if (S.output != int(Builtin::linear)) {
      for (int o = 0; o < S.out[l]; ++o) z[o] = act_any(S.output, z[o], S.op);
    }
  }
}

// f'(z) of unit vector i of hidden width block l, after a training forward pass.
template <int H>
SN_INLINE v8 hidden_grad(const View& V, int l, int i) {
  if constexpr (kFromOutput<H>) return act_grad_a<H>(V.act(l)[i], V.S.hp);
  return V.dz(l)[i];
}

// The loss of nn/loss.h per lane (lv) and its derivative by the prediction (lg), for the error
// e (0 in dead lanes) and the target t.
struct LossArgs {
  LossKind kind;
  float delta;
  float sample_limit = std::numeric_limits<float>::infinity();  // a sample's squared error above it: exploded
};
// step_impl's verdicts (nn/trainer.h's order: a non-finite loss, then a sample above the limit,
// then a non-finite update).
enum StepVerdict : int { kStepOk = 0, kStepNonfinite = 1, kStepExploded = 2 };
SN_INLINE void loss_both(const LossArgs& L, const v8& e, const v8& t, v8& lv, v8& lg) {
  switch (L.kind) {
    case LossKind::l1:
      lv = select(e < 0.0f, -e, e);
      lg = select(e > 0.0f, splat(1.0f), select(e < 0.0f, splat(-1.0f), splat(0.0f)));
      break;
    case LossKind::relative_l2: {
      const v8 inv = 1.0f / (t * t + float(kRelativeL2Eps));
      lv = e * e * inv;
      lg = 2.0f * e * inv;
      break;
    }
    case LossKind::huber: {
      const v8 a = select(e < 0.0f, -e, e), d = splat(L.delta);
      lv = select(a <= d, 0.5f * e * e, d * (a - 0.5f * d));  // NaN takes the second: stays NaN
      lg = select(e > d, d, select(e < -d, -d, e));
      break;
    }
    default:
      lv = e * e;
      lg = 2.0f * e;
  }
}

// Target rows as lanes (0 beyond n) and the lane mask.
SN_INLINE v8 gather_target(const float* y, int outputs, int o, const uint32_t* rows, std::size_t first, int n) {
  v8 t = splat(0.0f);
  for (int s = 0; s < n; ++s) t[s] = y[std::size_t(rows ? rows[first + s] : first + s) * outputs + o];
  return t;
}
SN_INLINE v8i lane_mask(int n) {
  const v8i lanes = {0, 1, 2, 3, 4, 5, 6, 7};
  return lanes < n;
}

template <class Isa, int H>
SN_INLINE int step_impl(const View& V, const float* x, const float* y, const uint32_t* rows, int batch, const AdamStep& c,
               const LossArgs& lf, double* loss_out) {
  const Layout& S = V.S;
  const float* p = V.p();
  float* g = V.base + S.o_g;
  std::memset(g, 0, S.P * sizeof(float));
  const int outputs = S.out[S.L - 1];
  const float scale = 2.0f / float(batch * outputs);  // l2's: d mean(e^2) / d y'
  const float mean = 1.0f / float(batch * outputs);
  // Each sample's loss (its outputs' sum) in float, the minibatch's sum in double, as the gl
  // kernel does: a step is refused by the same rule on both (nn/trainer.h).
  double loss_sum = 0;
  bool finite = true, too_big = false;
  for (int first = 0; first < batch; first += kLanes) {
    const int n = batch - first < kLanes ? batch - first : kLanes;
    v8 sq = splat(0.0f), se = splat(0.0f);
    gather_inputs(V, x, rows, std::size_t(first), n);
    forward_block<H, true>(V);
    // Output error: d = dloss/dy' * act'(y').
    const v8i mask = lane_mask(n);
    v8* d = V.d(0);
    const v8* yhat = V.act(S.L);
    for (int o = 0; o < outputs; ++o) {
      const v8 t = gather_target(y, outputs, o, rows, std::size_t(first), n);
      v8 diff = yhat[o] - t;
      diff = mask ? diff : splat(0.0f);
      v8 g;
      if (lf.kind == LossKind::l2) {
        sq += diff * diff;
        g = scale * diff;
      } else {
        v8 lv, lg;
        loss_both(lf, diff, t, lv, lg);
        sq += lv;
        se += diff * diff;
        g = mean * lg;
      }
      d[o] = S.output == int(Builtin::linear) ? g : g * V.dz(S.L)[o];
    }
    if (lf.kind == LossKind::l2) se = sq;
    for (int k = 0; k < n; ++k) {
      finite = finite && std::isfinite(sq[k]);
      too_big = too_big || se[k] > lf.sample_limit;
      loss_sum += double(sq[k]);
    }
    int cur = 0;
    for (int l = S.L - 1; l >= 0; --l) {
      const int in = S.in[l], out = S.out[l], inpad = S.inpad[l];
      v8* dl = V.d(cur);
      // Transposed activations for the outer-product gradient (pad columns stay 0).
      const float* a = reinterpret_cast<const float*>(V.act(l));
      float* aT = V.at(l);
      for (int i = 0; i < in; ++i)
        for (int s = 0; s < kLanes; ++s) aT[s * inpad + i] = a[i * kLanes + s];
      float* gb = g + S.boff[l];
      for (int o = 0; o < out; ++o) gb[o] += hsum(dl[o]);
      in_groups<Gradient>(out, g + S.woff[l], inpad, reinterpret_cast<const float*>(dl), aT);
      if (l == 0) break;
      v8* prev = V.d(cur ^ 1);
      in_groups<Backward>(in, p + S.woff[l], inpad, out, dl, prev);
      for (int i = 0; i < in; ++i) prev[i] *= hidden_grad<H>(V, l, i);
      cur ^= 1;
    }
  }
  const double loss = loss_sum / (double(batch) * outputs);
  *loss_out = loss;
  if (!finite || !std::isfinite(loss)) return kStepNonfinite;
  if (too_big) return kStepExploded;
  // Adam into the other parameter copy; the current one survives a non-finite result.
  const v8 b1 = splat(c.beta1), b2 = splat(c.beta2), ob1 = splat(1.0f - c.beta1), ob2 = splat(1.0f - c.beta2);
  const v8 lr = splat(c.lr * c.inv_c1), ic2 = splat(c.inv_c2), eps = splat(c.eps);
  v8* __restrict pn = reinterpret_cast<v8*>(V.pnext());
  const v8* __restrict pc = reinterpret_cast<const v8*>(p);
  v8* __restrict m = reinterpret_cast<v8*>(V.base + S.o_m);
  v8* __restrict v = reinterpret_cast<v8*>(V.base + S.o_v);
  const v8* __restrict gv = reinterpret_cast<const v8*>(g);
  v8 bad = splat(0.0f);  // w - w is 0 for finite w, NaN otherwise
  for (std::size_t j = 0; j < S.P / kLanes; ++j) {
    const v8 gj = gv[j];
    const v8 mj = b1 * m[j] + ob1 * gj;
    const v8 vj = b2 * v[j] + ob2 * gj * gj;
    m[j] = mj;
    v[j] = vj;
    const v8 w = pc[j] - lr * mj / (vsqrt<Isa>(vj * ic2) + eps);
    bad += w - w;
    pn[j] = w;
  }
  return hsum(bad) == 0.0f ? kStepOk : kStepNonfinite;
}

template <int H>
SN_INLINE double loss_impl(const View& V, const float* x, const float* y, std::size_t count, const LossArgs& lf) {
  const Layout& S = V.S;
  const int outputs = S.out[S.L - 1];
  double sum = 0;
  for (std::size_t first = 0; first < count; first += kLanes) {
    const int n = count - first < std::size_t(kLanes) ? int(count - first) : kLanes;
    gather_inputs(V, x, nullptr, first, n);
    forward_block<H>(V);
    const v8i mask = lane_mask(n);
    const v8* yhat = V.act(S.L);
    v8 sq = splat(0.0f);
    for (int o = 0; o < outputs; ++o) {
      const v8 t = gather_target(y, outputs, o, nullptr, first, n);
      v8 diff = yhat[o] - t;
      diff = mask ? diff : splat(0.0f);
      v8 lv, lg;
      loss_both(lf, diff, t, lv, lg);
      sq += lv;
    }
    sum += double(hsum(sq));
  }
  return count ? sum / (double(count) * outputs) : 0.0;
}

template <int H>
SN_INLINE void forward_impl(const View& V, const float* x, std::size_t count, float* out) {
  const Layout& S = V.S;
  const int outputs = S.out[S.L - 1];
  for (std::size_t first = 0; first < count; first += kLanes) {
    const int n = count - first < std::size_t(kLanes) ? int(count - first) : kLanes;
    gather_inputs(V, x, nullptr, first, n);
    forward_block<H>(V);
    const float* yhat = reinterpret_cast<const float*>(V.act(S.L));
    for (int s = 0; s < n; ++s)
      for (int o = 0; o < outputs; ++o) out[(first + s) * outputs + o] = yhat[o * kLanes + s];
  }
}

template <int H>
SN_INLINE void lanes_impl(const View& V, const float* x, std::size_t blocks, float* y) {
  const Layout& S = V.S;
  const std::size_t in = std::size_t(S.in[0]) * kLanes, out = std::size_t(S.out[S.L - 1]) * kLanes;
  for (std::size_t b = 0; b < blocks; ++b) {
    std::memcpy(V.act(0), x + b * in, in * sizeof(float));
    forward_block<H>(V);
    std::memcpy(y + b * out, V.act(S.L), out * sizeof(float));
  }
}

template <int H>
SN_INLINE void counts_impl(const View& V, const float* x, std::size_t count,
                           std::vector<std::vector<uint32_t>>& counts) {
  const Layout& S = V.S;
  std::size_t units = 0;
  for (int l = 1; l < S.L; ++l) units += std::size_t(S.in[l]);
  // Per unit and lane: -(number of samples that hit). Plain ints moved with memcpy: heap
  // memory from std::vector is only 16-byte aligned, and GCC stores vectors with aligned moves.
  std::vector<int32_t> hits(units * kLanes, 0);
  for (std::size_t first = 0; first < count; first += kLanes) {
    const int n = count - first < std::size_t(kLanes) ? int(count - first) : kLanes;
    gather_inputs(V, x, nullptr, first, n);
    forward_block<H, true>(V);
    const v8i valid = lane_mask(n);
    std::size_t u = 0;
    for (int l = 1; l < S.L; ++l) {
      const v8* a = V.act(l);
      for (int i = 0; i < S.in[l]; ++i, ++u) {
        v8i hit;
        if constexpr (H == int(Builtin::tanh)) hit = (a[i] > 0.99f) | (a[i] < -0.99f);
        else if constexpr (H == int(Builtin::sigmoid)) hit = (a[i] < 0.01f) | (a[i] > 0.99f);
        else if constexpr (H == int(Builtin::relu) || H == int(Builtin::leaky_relu)) hit = a[i] > 0.0f;
        else {
          const v8 g = hidden_grad<H>(V, l, i);
          hit = (g < 0.01f) & (g > -0.01f);  // flat: the unit passes (almost) no gradient
        }
        v8i h;
        std::memcpy(&h, &hits[u * kLanes], sizeof h);
        h += hit & valid;  // comparisons give -1 per true lane
        std::memcpy(&hits[u * kLanes], &h, sizeof h);
      }
    }
  }
  counts.assign(std::size_t(S.L - 1), {});
  std::size_t u = 0;
  for (int l = 1; l < S.L; ++l)
    for (int i = 0; i < S.in[l]; ++i, ++u) {
      int64_t total = 0;
      for (int s = 0; s < kLanes; ++s) total -= hits[u * kLanes + s];
      counts[l - 1].push_back(uint32_t(total));
    }
}

// The entry points per instruction set; everything above inlines into them.
using StepFn = int (*)(const View&, const float*, const float*, const uint32_t*, int, const AdamStep&, const LossArgs&,
                        double*);
using LossFn = double (*)(const View&, const float*, const float*, std::size_t, const LossArgs&);
using ForwardFn = void (*)(const View&, const float*, std::size_t, float*);
using CountsFn = void (*)(const View&, const float*, std::size_t, std::vector<std::vector<uint32_t>>&);
using LanesFn = void (*)(const View&, const float*, std::size_t, float*);

template <int H>
__attribute__((target("avx2,fma"))) int step_avx2(const View& V, const float* x, const float* y,
                                                   const uint32_t* rows, int batch, const AdamStep& c,
                                                   const LossArgs& lf, double* l) {
  return step_impl<Avx2, H>(V, x, y, rows, batch, c, lf, l);
}
template <int H>
__attribute__((target("avx2,fma"))) double loss_avx2(const View& V, const float* x, const float* y, std::size_t n,
                                                     const LossArgs& lf) {
  return loss_impl<H>(V, x, y, n, lf);
}
template <int H>
__attribute__((target("avx2,fma"))) void forward_avx2(const View& V, const float* x, std::size_t n, float* out) {
  forward_impl<H>(V, x, n, out);
}
template <int H>
__attribute__((target("avx2,fma"))) void lanes_avx2(const View& V, const float* x, std::size_t n, float* y) {
  lanes_impl<H>(V, x, n, y);
}
template <int H>
void lanes_sse2(const View& V, const float* x, std::size_t n, float* y) {
  lanes_impl<H>(V, x, n, y);
}
template <int H>
__attribute__((target("avx2,fma"))) void counts_avx2(const View& V, const float* x, std::size_t n,
                                                     std::vector<std::vector<uint32_t>>& counts) {
  counts_impl<H>(V, x, n, counts);
}
template <int H>
void counts_sse2(const View& V, const float* x, std::size_t n, std::vector<std::vector<uint32_t>>& counts) {
  counts_impl<H>(V, x, n, counts);
}
template <int H>
int step_sse2(const View& V, const float* x, const float* y, const uint32_t* rows, int batch, const AdamStep& c,
               const LossArgs& lf, double* l) {
  return step_impl<Sse2, H>(V, x, y, rows, batch, c, lf, l);
}

template <int K>
SN_INLINE void activation_impl(float p, const float* z, std::size_t n, float* f, float* df) {
  for (std::size_t i = 0; i < n; i += kLanes) {
    v8 zv = splat(0.0f);
    for (std::size_t k = 0; k < kLanes && i + k < n; ++k) zv[k] = z[i + k];
    v8 a, g;
    act_both<K>(zv, p, a, g);
    const v8 a_only = act<K>(zv, p);
    if constexpr (kFromOutput<K>) g = act_grad_a<K>(a_only, p);
    for (std::size_t k = 0; k < kLanes && i + k < n; ++k) f[i + k] = a_only[k], df[i + k] = g[k];
  }
}
template <int K>
__attribute__((target("avx2,fma"))) void activation_avx2(float p, const float* z, std::size_t n, float* f, float* df) {
  activation_impl<K>(p, z, n, f, df);
}
template <int K>
void activation_sse2(float p, const float* z, std::size_t n, float* f, float* df) {
  activation_impl<K>(p, z, n, f, df);
}

struct Kernels {
  StepFn step;
  LossFn loss;
  ForwardFn forward;
  CountsFn counts;
  LanesFn lanes;
};

template <int H>
Kernels kernels_for(bool avx2) {
  if (avx2) return {step_avx2<H>, loss_avx2<H>, forward_avx2<H>, counts_avx2<H>, lanes_avx2<H>};
  return {step_sse2<H>, loss_impl<H>, forward_impl<H>, counts_sse2<H>, lanes_sse2<H>};
}

bool cpu_has_avx2() {
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
}

std::atomic<bool>& avx2_flag() {
  static std::atomic<bool> flag = [] {
    const char* force = std::getenv("SHADENET_CPU_KERNEL");
    return !(force && std::string(force) == "sse2") && cpu_has_avx2();
  }();
  return flag;
}
bool use_avx2() { return avx2_flag().load(std::memory_order_relaxed); }

Kernels kernels(int hidden) {
  const bool avx2 = use_avx2();
  Kernels k{};
  with_builtin(hidden, [&](auto h) { k = kernels_for<decltype(h)::value>(avx2); });
  return k;
}

}  // namespace

void cpu_activation(Activation a, float param, const float* z, std::size_t n, float* f, float* df) {
  const int kind = activation_def(a).simd;
  if (kind < 0) throw std::invalid_argument(std::string("activation '") + activation_name(a) + "' has no cpu code");
  const bool avx2 = use_avx2();
  with_builtin(kind, [&](auto k) {
    constexpr int K = decltype(k)::value;
    (avx2 ? activation_avx2<K> : activation_sse2<K>)(param, z, n, f, df);
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

const char* cpu_kernel_name() { return use_avx2() ? "avx2" : "sse2"; }

void use_cpu_kernel(const std::string& name) {
  if (name == "avx2" && !cpu_has_avx2()) throw std::runtime_error("this CPU has no AVX2+FMA");
  if (name != "avx2" && name != "sse2") throw std::invalid_argument("unknown cpu kernel '" + name + "' (valid: avx2, sse2)");
  avx2_flag() = name == "avx2";
}

CpuNet::CpuNet(const MlpSpec& spec, const float* params) : spec_(spec), layout_(std::make_unique<Layout>(spec)) {
  const std::size_t bytes = layout_->total * sizeof(float);
  arena_ = static_cast<float*>(std::aligned_alloc(64, bytes));
  if (!arena_) throw std::bad_alloc();
  std::memset(arena_, 0, bytes);
  set_params(params);
}

CpuNet::~CpuNet() { std::free(arena_); }

void CpuNet::set_params(const float* flat) {
  const Layout& S = *layout_;
  float* p = arena_ + S.o_p[cur_];
  std::memset(p, 0, S.P * sizeof(float));
  for (int l = 0; l < S.L; ++l) {
    const float* w = flat + spec_.weight_offset(l);
    for (int o = 0; o < S.out[l]; ++o)
      std::memcpy(p + S.woff[l] + std::size_t(o) * S.inpad[l], w + std::size_t(o) * S.in[l], S.in[l] * sizeof(float));
    std::memcpy(p + S.boff[l], flat + spec_.bias_offset(l), S.out[l] * sizeof(float));
  }
  // The other copy's pad columns must be 0 too: Adam writes every float of it.
  std::memcpy(arena_ + S.o_p[cur_ ^ 1], p, S.P * sizeof(float));
  std::memset(arena_ + S.o_m, 0, 2 * S.P * sizeof(float));
}

namespace {
void unpack(const MlpSpec& spec, const Layout& S, const float* p, float* flat) {
  for (int l = 0; l < S.L; ++l) {
    float* w = flat + spec.weight_offset(l);
    for (int o = 0; o < S.out[l]; ++o)
      std::memcpy(w + std::size_t(o) * S.in[l], p + S.woff[l] + std::size_t(o) * S.inpad[l], S.in[l] * sizeof(float));
    std::memcpy(flat + spec.bias_offset(l), p + S.boff[l], S.out[l] * sizeof(float));
  }
}
}  // namespace

void CpuNet::get_params(float* flat) const { unpack(spec_, *layout_, arena_ + layout_->o_p[cur_], flat); }

void CpuNet::get_gradient(float* flat) const { unpack(spec_, *layout_, arena_ + layout_->o_g, flat); }

bool CpuNet::step(const float* x, const float* y, const uint32_t* rows, int batch, const AdamStep& adam,
                  double* loss, DivergenceKind* why) {
  const View V{*layout_, arena_, cur_};
  const int verdict =
      kernels(layout_->hidden).step(V, x, y, rows, batch, adam, LossArgs{loss_.kind, float(loss_.delta), sample_limit_}, loss);
  if (verdict != kStepOk) {
    if (why) *why = verdict == kStepExploded ? DivergenceKind::exploded : DivergenceKind::nonfinite;
    return false;
  }
  cur_ ^= 1;
  return true;
}

double CpuNet::mse(const float* x, const float* y, std::size_t count) {
  return kernels(layout_->hidden).loss(View{*layout_, arena_, cur_}, x, y, count, LossArgs{LossKind::l2, 1.0f});
}

double CpuNet::mean_loss(const float* x, const float* y, std::size_t count) {
  return kernels(layout_->hidden).loss(View{*layout_, arena_, cur_}, x, y, count, LossArgs{loss_.kind, float(loss_.delta)});
}

void CpuNet::forward(const float* x, std::size_t count, float* out) {
  kernels(layout_->hidden).forward(View{*layout_, arena_, cur_}, x, count, out);
}

void CpuNet::forward_lanes(const float* x, std::size_t blocks, float* y) {
  kernels(layout_->hidden).lanes(View{*layout_, arena_, cur_}, x, blocks, y);
}

std::vector<std::vector<uint32_t>> CpuNet::unit_counts(const float* x, std::size_t count) {
  std::vector<std::vector<uint32_t>> counts;
  kernels(layout_->hidden).counts(View{*layout_, arena_, cur_}, x, count, counts);
  return counts;
}

}  // namespace sn::nn

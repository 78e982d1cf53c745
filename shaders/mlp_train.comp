// Fused training of many networks of one architecture (driven by runtime/nn/gl_trainer.cpp).
// Workgroup n trains network n for ctl[n].limit minibatch steps in one dispatch. Invocation
// `lane` carries sample `lane` of each minibatch through forward and backward; then lane j
// updates the weight rows j, j + MLP_BATCH, ... with the minibatch gradient summed over the
// samples in a fixed order (deterministic) and Adam. Parameters are in the padded vec4 layout
// of runtime/nn/mlp_shader.h. Results reach the state buffer only when the dispatch is sound (the
// kernel writes them to `staged`, the host copies them: mlp/train_io.glsl):
//  - llvmpipe ends every loop of an invocation after 65,535 iterations in total; a check after
//    the last loop notices (mlp/loop_limit.glsl), and the dispatch commits nothing (status 3);
//  - a step whose loss or deltas are not finite stops the net before its update (status 1,
//    the parameters committed are the last finite ones); so does one in which a sample's squared
//    error is above the net's sample_limit (status 4; a non-finite loss goes first, then this,
//    then non-finite deltas, as runtime/nn/cpu_net.cpp checks them);
//  - a step whose new parameters are not finite commits nothing (status 2): the host re-runs
//    the chunk one step short of it.
#include "mlp/activation.glsl"
#include "mlp/encoding.glsl"
#include "mlp/adam.glsl"
#include "mlp/loss.glsl"

layout(local_size_x = MLP_BATCH) in;

#include "mlp/train_io.glsl"
#include "mlp/loop_limit.glsl"
layout(std430, binding = 4) buffer Scratch { vec4 scratch[]; };  // per net: arrays not in shared memory

#define B MLP_BATCH
#define MLP_ROLLED(n) ((n) + u_zero)
#define UD (MLP_UQ - MLP_IN4)  // unit vec4s with a delta (all but the inputs)

uint scratch_base;

#if MLP_PARAMS_SHARED
shared vec4 sh_p[MLP_PQ];
#define P4(k) sh_p[k]
#define SCR_M 0
#else
#define P4(k) scratch[scratch_base + uint(k)]
#define SCR_M MLP_PQ
#endif

#if MLP_MOMENTS_SHARED
shared vec4 sh_m[MLP_PQ];
shared vec4 sh_v[MLP_PQ];
#define M4(k) sh_m[k]
#define V4(k) sh_v[k]
#define SCR_U SCR_M
#else
#define M4(k) scratch[scratch_base + uint(SCR_M + (k))]
#define V4(k) scratch[scratch_base + uint(SCR_M + MLP_PQ + (k))]
#define SCR_U (SCR_M + 2 * MLP_PQ)
#endif

// Every sample's units (activations) and deltas, sample-major: what the update sums over.
#if MLP_UNITS_SHARED
shared vec4 sh_a[B * MLP_UQ];
shared vec4 sh_d[B * UD];
#define A4(s, k) sh_a[(s) * MLP_UQ + (k)]
#define D4(s, k) sh_d[(s) * UD + (k) - MLP_IN4]
#else
#define A4(s, k) scratch[scratch_base + uint(SCR_U + (s) * MLP_UQ + (k))]
#define D4(s, k) scratch[scratch_base + uint(SCR_U + B * MLP_UQ + (s) * UD + (k) - MLP_IN4)]
#endif

shared uint sh_bad;   // some sample's loss or delta is not finite: stop before the update
shared uint sh_bad_loss;  // some sample's loss is not finite
shared uint sh_big;   // some sample's squared error is above the limit
shared uint sh_late;  // some new parameter is not finite
shared uint sh_cut;   // the loop limiter ended a loop early
shared double sh_loss[B];

#define SYNC()           \
  memoryBarrierShared(); \
  memoryBarrierBuffer(); \
  barrier()

int lane;
float bc1, bc2;

void adam_at(int k, vec4 g, bvec4 live) {
  vec4 m = M4(k), v = V4(k);
  vec4 w = mlp_adam(m, v, P4(k), g, u_lr, u_beta1, u_beta2, u_eps, bc1, bc2, live);
  if (!mlp_finite(w)) sh_late = 1u;
  P4(k) = w;
  M4(k) = m;
  V4(k) = v;
}

#define MLP_P4(k) P4(k)
#define MLP_UNIT(b, u0, k) A4(lane, (u0) + (k))
// f'(z) of activations that need z waits in the unit's delta slot until backward overwrites it.
#define MLP_KEEP_GRAD(u, g) D4(lane, u) = (g);
#include "mlp/forward.glsl"

// This sample's deltas of a layer's inputs from those of its outputs (not for the first layer):
// delta_i = f'(z_i) * sum_j W[j][i] delta_j, rows in order; runs last layer first.
#define BACKWARD_RUN(L0, COUNT, IN, OUT, IN4, OUT4, WQ0, UI0, QN)                    \
  for (int r_ = 0; r_ < MLP_ROLLED(COUNT); ++r_) {                                   \
    const int k_ = COUNT - 1 - r_, wq_ = WQ0 + k_ * (OUT * IN4 + OUT4);              \
    const int ui_ = UI0 + k_ * IN4, uo_ = ui_ + IN4;                                 \
    vec4 acc[IN4];                                                                   \
    for (int q = 0; q < QN; ++q) acc[q] = vec4(0.0);                                 \
    for (int jq = 0; jq < MLP_ROLLED(OUT4); ++jq) {                                  \
      vec4 dq = D4(lane, uo_ + jq);                                                  \
      for (int c = 0; c < 4; ++c) {                                                  \
        int j = min(4 * jq + c, OUT - 1); /* padding: the last row times delta 0 */  \
        for (int q = 0; q < QN; ++q) acc[q] += P4(wq_ + j * IN4 + q) * dq[c];        \
      }                                                                              \
    }                                                                                \
    for (int q = 0; q < QN; ++q) {                                                   \
      vec4 dq = acc[q] * MLP_ACT_DERIV(A4(lane, ui_ + q), D4(lane, ui_ + q));        \
      ok = ok && mlp_finite(dq);                                                     \
      D4(lane, ui_ + q) = dq;                                                        \
    }                                                                                \
  }

// The minibatch gradient of a layer and its Adam step: lane j takes weight rows j, j + B, ...;
// the biases go a vec4 per lane. Sums over samples run s = 0, 1, ... (deterministic).
#define UPDATE_RUN(L0, COUNT, IN, OUT, IN4, OUT4, WQ0, UI0, QN)                          \
  for (int k_ = 0; k_ < MLP_ROLLED(COUNT); ++k_) {                                       \
    const int wq_ = WQ0 + k_ * (OUT * IN4 + OUT4), bq_ = wq_ + OUT * IN4;                \
    const int ui_ = UI0 + k_ * IN4, uo_ = ui_ + IN4;                                     \
    for (int jg = 0; jg < MLP_ROLLED((OUT + B - 1) / B); ++jg) {                         \
      int j = jg * B + lane;                                                             \
      if (j < OUT) {                                                                     \
        float ds[B];                                                                     \
        for (int s = 0; s < B; ++s) ds[s] = D4(s, uo_ + (j >> 2))[j & 3];                 \
        for (int q = 0; q < QN; ++q) {                                                   \
          vec4 g = vec4(0.0);                                                            \
          for (int s = 0; s < B; ++s) g += ds[s] * A4(s, ui_ + q);                       \
          adam_at(wq_ + j * IN4 + q, g, mlp_live(q, IN));                                \
        }                                                                                \
      }                                                                                  \
    }                                                                                    \
    for (int bg = 0; bg < MLP_ROLLED((OUT4 + B - 1) / B); ++bg) {                        \
      int q = bg * B + lane;                                                             \
      if (q < OUT4) {                                                                    \
        vec4 g = vec4(0.0);                                                              \
        for (int s = 0; s < B; ++s) g += D4(s, uo_ + q);                                 \
        adam_at(bq_ + q, g, mlp_live(q, OUT));                                           \
      }                                                                                  \
    }                                                                                    \
  }

void main() {
  const uint net = gl_WorkGroupID.x;
  lane = int(gl_LocalInvocationIndex);
  const int limit = ctl[net].limit;
  if (limit <= 0) return;  // the same for the whole workgroup
  scratch_base = net * uint(MLP_SCRATCH);
  const uint base = net * uint(3 * MLP_PQ);

  for (int k = 0; k < MLP_ROLLED((MLP_PQ + B - 1) / B); ++k) {
    int p = k * B + lane;
    if (p < MLP_PQ) {
      P4(p) = state[base + uint(p)];
      M4(p) = state[base + uint(MLP_PQ + p)];
      V4(p) = state[base + uint(2 * MLP_PQ + p)];
    }
  }
  if (lane == 0) {
    sh_bad = 0u;
    sh_bad_loss = 0u;
    sh_big = 0u;
    sh_late = 0u;
    sh_cut = 0u;
  }
  SYNC();

  uint t = ctl[net].t0;
  const uint first_row = ctl[net].first_row;
  const float sample_limit = ctl[net].sample_limit;
  double loss_sum = 0.0lf;
  int done = 0, status = 0;
  for (int step = 0; step < limit; ++step) {
    uint row = order[first_row + uint(step * B + lane)];
#if MLP_ENCODED
    float raw[MLP_RAW_IN];
    for (int i = 0; i < MLP_RAW_IN; ++i) raw[i] = train_x[row * uint(MLP_RAW_IN) + uint(i)];
    vec4 enc[MLP_IN4];
    mlp_encode(raw, enc);
    for (int q = 0; q < MLP_IN4; ++q) A4(lane, q) = enc[q];
#else
    for (int q = 0; q < MLP_IN4; ++q) {
      vec4 x = vec4(0.0);
      for (int c = 0; c < 4; ++c)
        if (4 * q + c < MLP_IN) x[c] = train_x[row * uint(MLP_IN) + uint(4 * q + c)];
      A4(lane, q) = x;
    }
#endif
    MLP_FORWARD()

    // d/dy of the mean loss over the minibatch's samples and outputs (mlp/loss.glsl), then backward.
    bool ok = true;
    float loss = 0.0, se = 0.0;
    for (int q = 0; q < MLP_OUT4; ++q) {
      vec4 y = A4(lane, MLP_OUT_UQ + q), target = vec4(0.0);
      for (int c = 0; c < 4; ++c)
        if (4 * q + c < MLP_OUT) target[c] = train_y[row * uint(MLP_OUT) + uint(4 * q + c)];
      vec4 e = mix(vec4(0.0), y - target, mlp_live(q, MLP_OUT));
      loss += dot(mlp_loss(e, target), vec4(1.0));
      se += dot(e, e);
      vec4 dq = (1.0 / float(B * MLP_OUT)) * mlp_loss_grad(e, target) * MLP_OUT_ACT_DERIV(y, D4(lane, MLP_OUT_UQ + q));
      ok = ok && mlp_finite(dq);
      D4(lane, MLP_OUT_UQ + q) = dq;
    }
    if (!mlp_finite(loss)) sh_bad_loss = 1u;
    if (MLP_SQUARED_ERROR(loss, se) > sample_limit) sh_big = 1u;
    MLP_INNER_RUN_TABLE_REVERSED(BACKWARD_RUN)
    if (!ok) sh_bad = 1u;
    SYNC();
    if ((sh_bad | sh_bad_loss | sh_big) != 0u && u_probe == 0) {
      status = sh_bad_loss != 0u ? 1 : (sh_big != 0u ? 4 : 1);
      break;
    }

    t += 1u;
    vec2 bc = t <= u_bias_len ? bias[t - 1u] : vec2(1.0);
    bc1 = bc.x;
    bc2 = bc.y;
    MLP_RUN_TABLE(UPDATE_RUN)
    SYNC();
    loss_sum += double(loss);
    done = step + 1;
    if (sh_late != 0u && u_probe == 0) {
      status = 2;
      break;
    }
  }

  // A probe run counts the loop budget its steps left (runtime/nn/gl_trainer.cpp, plan_chunks).
  int count = 0;
  if (u_probe != 0)
    for (int k = 0; k < u_probe_count; ++k) ++count;
  sh_loss[lane] = loss_sum;
  SYNC();
  if (lane == 0) {
    double total = 0.0lf;
    for (int s = 0; s < B; ++s) total += sh_loss[s];
    ctl[net].loss_sum += total;
  }
  if (status != 2 && u_probe == 0) {
    for (int k = 0; k < MLP_ROLLED((MLP_PQ + B - 1) / B); ++k) {
      int p = k * B + lane;
      if (p < MLP_PQ) {
        staged[base + uint(p)] = P4(p);
        staged[base + uint(MLP_PQ + p)] = M4(p);
        staged[base + uint(2 * MLP_PQ + p)] = V4(p);
      }
    }
  }
  // After every other loop: was any cut short? Then the host keeps nothing of this dispatch.
  if (mlp_loops_were_cut()) sh_cut = 1u;
  SYNC();
  if (lane == 0) {
    ctl[net].done = done;
    ctl[net].status = sh_cut != 0u ? 3 : status;
    ctl[net].remaining = count;
  }
}

// Fused training with one invocation per network (driven by runtime/nn/gl_trainer.cpp; the
// kernel it picks for small networks on a CPU renderer). Invocation n trains network n for
// ctl[n].limit minibatch steps in one dispatch, alone: it keeps the parameters, the Adam moments,
// the minibatch gradient and one sample's units and deltas in registers, carries the samples of
// each minibatch through forward and backward one after another, summing the gradient in sample
// order (deterministic), then takes the Adam step. On llvmpipe an invocation is a SIMD lane and
// every shared-memory or storage-buffer access a loop over the lanes; here a step reads its
// samples' rows through buffer textures (gathers) and touches no other memory.
//
// The arrays stay in registers only while every index is a literal: the step is straight-line
// code written per architecture by runtime/nn/mlp_per_net.cpp (the MLP_R_* defines). Results
// reach the state buffer only when the dispatch is sound, as in mlp_train.comp (written to
// `staged`, copied by the host: mlp/train_io.glsl):
//  - llvmpipe ends every loop of an invocation after 65,535 iterations in total; a check after
//    the last loop notices (mlp/loop_limit.glsl), and the dispatch commits nothing (status 3);
//  - a step whose loss or deltas are not finite stops the net before its update (status 1); so
//    does one in which a sample's squared error is above the net's sample_limit (status 4; a
//    non-finite loss goes first, then this, then non-finite deltas, as the cpu backend checks);
//  - a step whose new parameters are not finite commits nothing (status 2).
#include "mlp/activation.glsl"
#include "mlp/encoding.glsl"
#include "mlp/adam.glsl"
#include "mlp/loss.glsl"

layout(local_size_x = MLP_NETS_PER_GROUP) in;

#include "mlp/train_io.glsl"
#include "mlp/loop_limit.glsl"
// The same buffers as textures, for reading.
layout(binding = 0) uniform samplerBuffer u_state;
layout(binding = 1) uniform samplerBuffer u_train_x;
layout(binding = 2) uniform samplerBuffer u_train_y;
layout(binding = 3) uniform usamplerBuffer u_order;

#define B MLP_BATCH
// Networks are dealt to workgroups in turn (net = lane * u_groups + workgroup), so a few
// networks still spread over every thread of the renderer.
uniform uint u_groups;

vec4 r_p[MLP_PQ], r_m[MLP_PQ], r_v[MLP_PQ], r_g[MLP_PQ];  // parameters, moments, gradient
vec4 r_a[MLP_UQ], r_d[MLP_UQ];                            // one sample's units and deltas

float bc1, bc2;
bool late;  // some new parameter is not finite

void adam_at(int k, bvec4 live) {
  vec4 m = r_m[k], v = r_v[k];
  vec4 w = mlp_adam(m, v, r_p[k], r_g[k], u_lr, u_beta1, u_beta2, u_eps, bc1, bc2, live);
  late = late || !mlp_finite(w);
  r_p[k] = w;
  r_m[k] = m;
  r_v[k] = v;
}

void main() {
  const uint net = gl_LocalInvocationID.x * u_groups + gl_WorkGroupID.x;
  if (net >= uint(ctl.length())) return;
  const int limit = ctl[net].limit;
  if (limit <= 0) return;
  const int base = int(net) * 3 * MLP_PQ;
  MLP_R_LOAD(base)
  late = false;

  uint t = ctl[net].t0;
  const uint first_row = ctl[net].first_row;
  const float sample_limit = ctl[net].sample_limit;
  double loss_sum = 0.0lf;
  int done = 0, status = 0;
  for (int step = 0; step < limit; ++step) {
    MLP_R_ZERO
    bool ok = true, loss_ok = true, big = false;
    double step_loss = 0.0lf;
    for (int s = 0; s < B; ++s) {
      const int row = int(texelFetch(u_order, int(first_row) + step * B + s).r);
      float loss = 0.0, se = 0.0;
      MLP_R_INPUTS(row)
      MLP_R_FORWARD
      MLP_R_OUTPUT(row)
      loss_ok = loss_ok && mlp_finite(loss);
      big = big || MLP_SQUARED_ERROR(loss, se) > sample_limit;
      MLP_R_BACKWARD
      MLP_R_ACCUMULATE
      step_loss += double(loss);
    }
    if (!(ok && loss_ok && !big) && u_probe == 0) {
      status = !loss_ok ? 1 : (big ? 4 : 1);
      break;
    }
    t += 1u;
    vec2 bc = t <= u_bias_len ? bias[t - 1u] : vec2(1.0);
    bc1 = bc.x;
    bc2 = bc.y;
    MLP_R_ADAM
    loss_sum += step_loss;
    done = step + 1;
    if (late && u_probe == 0) {
      status = 2;
      break;
    }
  }

  // A probe run counts the loop budget its steps left (runtime/nn/gl_trainer.cpp, plan_chunks).
  int count = 0;
  if (u_probe != 0)
    for (int k = 0; k < u_probe_count; ++k) ++count;
  ctl[net].loss_sum += loss_sum;
  if (status != 2 && u_probe == 0) {
    // One store of each kind per pass, the value picked by selects: written out straight, the
    // stores (each a loop over the lanes) took LLVM most of the compile time.
    for (int k = 0; k < MLP_PQ; ++k) {
      vec4 p = vec4(0.0), m = vec4(0.0), v = vec4(0.0);
      MLP_R_PICK(k)
      staged[base + k] = p;
      staged[base + MLP_PQ + k] = m;
      staged[base + 2 * MLP_PQ + k] = v;
    }
  }
  // After every other loop: was any cut short? Then the host keeps nothing of this dispatch.
  const bool cut = mlp_loops_were_cut();
  ctl[net].done = done;
  ctl[net].status = cut ? 3 : status;
  ctl[net].remaining = count;
}

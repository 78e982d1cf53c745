// What both fused training kernels (mlp_train.comp: an invocation per sample; mlp_train_per_net.comp:
// an invocation per network) share with runtime/nn/gl_trainer.cpp: the buffers, the control
// block of each network and the uniforms. Binding 4 is left to a kernel's own scratch buffer.
//
// A dispatch writes each network's new parameters and moments to `staged`, never to `state`: the
// host copies them over only when the dispatch reports no loop cut short (mlp/loop_limit.glsl,
// checked after every loop, the copy's included), so a cut dispatch leaves `state` as it was.
layout(std430, binding = 0) readonly buffer TrainX { float train_x[]; };
layout(std430, binding = 1) readonly buffer TrainY { float train_y[]; };
layout(std430, binding = 2) readonly buffer Order { uint order[]; };  // this epoch's row permutation
layout(std430, binding = 3) readonly buffer State { vec4 state[]; };   // per net: params, m, v (padded)
layout(std430, binding = 7) writeonly buffer Staged { vec4 staged[]; };  // the same layout: what a dispatch made
// Mirrored by GlControl in runtime/nn/gl_trainer.cpp (std430: 40 bytes).
struct NetControl {
  int limit;           // in: steps to run (0: skip this net)
  int done;            // out: steps that ran to their end
  int status;          // out: 0 ok, 1 stopped before a non-finite step, 2 non-finite update, 3 cut short,
                       //      4 stopped before a step with a sample's squared error above sample_limit
  int remaining;       // out, probe runs: the loop budget left after their steps
  uint first_row;      // in: index into order[] of the first sample
  uint t0;             // in: Adam steps applied before the first
  float sample_limit;  // in: the divergence rule's bound on a sample's squared error (runtime/nn/trainer.h)
  int pad_;
  double loss_sum;     // in/out: sum over applied steps of the minibatch's squared errors (kept by the host
                       //         only from a dispatch whose state it commits)
};
layout(std430, binding = 5) buffer Control { NetControl ctl[]; };
// Adam's bias corrections (1 - beta1^t, 1 - beta2^t) for t = 1..u_bias_len, computed on the host
// in double as the oracle does them; past the table both round to 1 in float.
layout(std430, binding = 6) readonly buffer Bias { vec2 bias[]; };

uniform float u_lr, u_beta1, u_beta2, u_eps;
uniform uint u_bias_len;
uniform int u_probe;        // 1: measure the loop budget, stage nothing
uniform int u_probe_count;  // probe runs: the bound of the loop that counts the budget left, far above it
uniform int u_zero;         // never set: 0, a loop bound the compiler cannot see through

// What both fused training kernels (mlp_train.comp: an invocation per sample; mlp_train_per_net.comp:
// an invocation per network) share with runtime/nn/gl_trainer.cpp: the buffers, the control
// block of each network and the uniforms. Binding 4 is left to a kernel's own scratch buffer.
layout(std430, binding = 0) readonly buffer TrainX { float train_x[]; };
layout(std430, binding = 1) readonly buffer TrainY { float train_y[]; };
layout(std430, binding = 2) readonly buffer Order { uint order[]; };  // this epoch's row permutation
layout(std430, binding = 3) buffer State { vec4 state[]; };           // per net: params, m, v (padded)
// Mirrored by GlControl in runtime/nn/gl_trainer.cpp (std430: 40 bytes).
struct NetControl {
  int limit;           // in: steps to run (0: skip this net)
  int done;            // out: steps that ran to their end
  int status;          // out: 0 ok, 1 stopped before a non-finite step, 2 non-finite update, 3 cut short,
                       //      4 stopped before a step with a sample's squared error above sample_limit
  int remaining;       // out: what the sentinel loop counted (the loop budget left, in probe runs)
  uint first_row;      // in: index into order[] of the first sample
  uint t0;             // in: Adam steps applied before the first
  float sample_limit;  // in: the divergence rule's bound on a sample's squared error (runtime/nn/trainer.h)
  int pad_;
  double loss_sum;     // in/out: sum over applied steps of the minibatch's squared errors
};
layout(std430, binding = 5) buffer Control { NetControl ctl[]; };
// Adam's bias corrections (1 - beta1^t, 1 - beta2^t) for t = 1..u_bias_len, computed on the host
// in double as the oracle does them; past the table both round to 1 in float.
layout(std430, binding = 6) readonly buffer Bias { vec2 bias[]; };

uniform float u_lr, u_beta1, u_beta2, u_eps;
uniform uint u_bias_len;
uniform int u_sentinel;  // the loop budget the commit needs (or far more in a probe run)
uniform int u_probe;     // 1: measure the loop budget, commit nothing

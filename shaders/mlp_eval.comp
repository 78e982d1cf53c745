// Networks of one architecture evaluated over rows of samples (runtime/nn/gl_forward.cpp):
// invocation = row, workgroup row y = network; parameters in the padded vec4 layout of
// runtime/nn/mlp_shader.h. MLP_EVAL_LOSS 1 writes, per network and workgroup, the sum of
// the loss (mlp/loss.glsl: squared errors for l2) against the targets (validation MSE without
// reading outputs back); 0 writes the outputs themselves.
layout(local_size_x = MLP_EVAL_LOCAL_SIZE) in;

layout(std430, binding = 0) readonly buffer X { float xs[]; };       // rows x MLP_RAW_IN
layout(std430, binding = 1) readonly buffer Y { float ys[]; };       // rows x MLP_OUT (loss mode)
layout(std430, binding = 2) readonly buffer Params { vec4 params[]; };
layout(std430, binding = 3) writeonly buffer Out { float outs[]; };  // per net: rows x MLP_OUT
layout(std430, binding = 4) writeonly buffer Partial { double partial[]; };  // per net: one per workgroup
layout(std430, binding = 5) buffer Cut { uint cut[]; };             // per net: 1 when the loop limiter ended a loop

uniform uint u_rows;          // rows in xs
uniform uint u_first_group;   // workgroup offset of this dispatch (large inputs take several)
uniform uint u_param_offset;  // first parameter vec4 of network 0
uniform uint u_param_stride;  // vec4s from one network's parameters to the next
uniform uint u_partials;      // partial sums per network
uniform int u_zero;  // never set: 0, a loop bound the compiler cannot see through
#include "mlp/loop_limit.glsl"

shared vec4 sh_u[MLP_EVAL_LOCAL_SIZE * MLP_UQ];  // each row's units

uint pbase, lane;
#define MLP_P4(k) params[pbase + uint(k)]
#define MLP_UNIT(b, u0, k) sh_u[lane * uint(MLP_UQ) + uint((u0) + (k))]
#define MLP_ROLLED(n) ((n) + u_zero)
#include "mlp/forward.glsl"
#include "mlp/encoding.glsl"
#include "mlp/loss.glsl"

#if MLP_EVAL_LOSS
shared double sh_sum[MLP_EVAL_LOCAL_SIZE];
#endif

void main() {
  const uint net = gl_WorkGroupID.y;
  lane = gl_LocalInvocationIndex;
  const uint group = u_first_group + gl_WorkGroupID.x;
  const uint row = group * uint(MLP_EVAL_LOCAL_SIZE) + lane;
  pbase = u_param_offset + net * u_param_stride;
  const bool live = row < u_rows;
  const uint r = live ? row : 0u;  // a dead row computes row 0 and drops it
#if MLP_ENCODED
  float raw[MLP_RAW_IN];
  for (int i = 0; i < MLP_RAW_IN; ++i) raw[i] = xs[r * uint(MLP_RAW_IN) + uint(i)];
  vec4 enc[MLP_IN4];
  mlp_encode(raw, enc);
  for (int q = 0; q < MLP_IN4; ++q) MLP_UNIT(0, 0, q) = enc[q];
#else
  for (int q = 0; q < MLP_IN4; ++q) {
    vec4 x = vec4(0.0);
    for (int c = 0; c < 4; ++c)
      if (4 * q + c < MLP_IN) x[c] = xs[r * uint(MLP_IN) + uint(4 * q + c)];
    MLP_UNIT(0, 0, q) = x;
  }
#endif
  MLP_FORWARD()

#if MLP_EVAL_LOSS
  double se = 0.0lf;
  for (int o = 0; o < MLP_OUT; ++o) {
    float t = ys[r * uint(MLP_OUT) + uint(o)], e = MLP_UNIT(MLP_LAYERS, MLP_OUT_UQ, o / 4)[o % 4] - t;
    se += double(mlp_loss(vec4(e), vec4(t)).x);
  }
  sh_sum[lane] = live ? se : 0.0lf;
  barrier();
  if (lane == 0u) {
    double total = 0.0lf;
    for (int k = 0; k < MLP_EVAL_LOCAL_SIZE; ++k) total += sh_sum[k];
    partial[net * u_partials + group] = total;
  }
#else
  if (live)
    for (int o = 0; o < MLP_OUT; ++o)
      outs[(net * u_rows + row) * uint(MLP_OUT) + uint(o)] = MLP_UNIT(MLP_LAYERS, MLP_OUT_UQ, o / 4)[o % 4];
#endif
  // After every other loop: llvmpipe's loop limiter cut one short, the results are not to be used.
  if (mlp_loops_were_cut()) cut[net] = 1u;
}

// Networks of one architecture evaluated over rows of samples (runtime/nn/gl_forward.cpp):
// invocation = row, workgroup row y = network. MLP_EVAL_LOSS 1 writes, per network and
// workgroup, the sum of squared errors against the targets (validation MSE without reading the
// outputs back); 0 writes the outputs themselves.
#include "mlp/activation.glsl"

layout(local_size_x = MLP_EVAL_LOCAL_SIZE) in;

layout(std430, binding = 0) readonly buffer X { float xs[]; };       // rows x MLP_IN
layout(std430, binding = 1) readonly buffer Y { float ys[]; };       // rows x MLP_OUT (loss mode)
layout(std430, binding = 2) readonly buffer Params { float params[]; };
layout(std430, binding = 3) writeonly buffer Out { float outs[]; };  // per net: rows x MLP_OUT
layout(std430, binding = 4) writeonly buffer Partial { double partial[]; };  // per net: one per workgroup
layout(std430, binding = 5) buffer Cut { uint cut[]; };             // per net: 1 when the loop limiter ended a loop

uniform uint u_rows;          // rows in xs
uniform uint u_first_group;   // workgroup offset of this dispatch (large inputs take several)
uniform uint u_param_offset;  // first parameter of network 0 in params[]
uniform uint u_param_stride;  // floats from one network's parameters to the next
uniform uint u_partials;      // partial sums per network
uniform int u_sentinel;

#if MLP_EVAL_SHARED_WEIGHTS
shared float sh_w[MLP_PARAMS];
#define MLP_W(p) sh_w[p]
#else
#define MLP_W(p) params[pbase + uint(p)]
#endif
#include "mlp/forward.glsl"

#if MLP_EVAL_LOSS
shared double sh_sum[MLP_EVAL_LOCAL_SIZE];
#endif

void main() {
  const uint net = gl_WorkGroupID.y;
  const uint lane = gl_LocalInvocationIndex;
  const uint group = u_first_group + gl_WorkGroupID.x;
  const uint row = group * uint(MLP_EVAL_LOCAL_SIZE) + lane;
  const uint pbase = u_param_offset + net * u_param_stride;
#if MLP_EVAL_SHARED_WEIGHTS
  for (uint p = lane; p < uint(MLP_PARAMS); p += uint(MLP_EVAL_LOCAL_SIZE)) sh_w[p] = params[pbase + p];
  barrier();
#endif
  const bool live = row < u_rows;
  float u[MLP_UNITS];
  for (int i = 0; i < MLP_IN; ++i) u[i] = live ? xs[row * uint(MLP_IN) + uint(i)] : 0.0;
  MLP_FORWARD()

  // Once llvmpipe's loop limiter is spent every loop stops after one pass: flag the result.
  int count = 0;
  for (int k = 0; k < u_sentinel; ++k) ++count;
  if (count < u_sentinel) cut[net] = 1u;

#if MLP_EVAL_LOSS
  double se = 0.0lf;
  if (live)
    for (int j = 0; j < MLP_OUT; ++j) {
      float e = u[MLP_OUT_UNIT + j] - ys[row * uint(MLP_OUT) + uint(j)];
      se += double(e * e);
    }
  sh_sum[lane] = se;
  barrier();
  for (uint half_ = uint(MLP_EVAL_LOCAL_SIZE) / 2u; half_ > 0u; half_ /= 2u) {
    if (lane < half_) sh_sum[lane] += sh_sum[lane + half_];
    barrier();
  }
  if (lane == 0u) partial[net * u_partials + group] = sh_sum[0];
#else
  if (live)
    for (int j = 0; j < MLP_OUT; ++j) outs[(net * u_rows + row) * uint(MLP_OUT) + uint(j)] = u[MLP_OUT_UNIT + j];
#endif
}

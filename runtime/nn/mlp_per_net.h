// The per-network training kernel (shaders/mlp_train_per_net.comp): one invocation trains one
// network, keeping its parameters, Adam moments, gradient and one sample's units and deltas in
// private arrays. Those stay in registers only if every index is a literal, and GLSL compilers
// do not unroll loops this long, so the step is written out here as straight-line GLSL for one
// architecture and batch, one #define per phase.
//
// It is the fast kernel on a CPU renderer such as llvmpipe, where an invocation is a SIMD lane
// and every shared-memory or storage-buffer access a loop over the lanes; a GPU wants the
// per-sample kernel (mlp_train.comp). docs/performance.md has the measurements.
#pragma once
#include <cstddef>

#include "gl/shader_source.h"
#include "nn/mlp_spec.h"

namespace sn::nn {

// Networks up to this many padded parameter vec4s get the per-network kernel (4x6 has 63, 8x8
// 151). LLVM's time and memory to compile grow faster than the straight-line code (llvmpipe,
// cold: 4x6 1 s; 8x8 4 s and 115 MiB more peak memory; 8x12 14 s; 12x12 38 s; see
// docs/performance.md).
constexpr std::size_t kPerNetMaxChunks = 128;
// Invocations (networks) per workgroup: one SIMD vector of llvmpipe. Fewer networks than
// workgroups x this are dealt out so that every renderer thread gets some.
constexpr int kNetsPerGroup = 8;

// The phases of one step over the kernel's arrays r_p, r_m, r_v, r_g (parameters, moments and
// gradient in the padded vec4 layout of nn/mlp_shader.h) and r_a, r_d (one sample's units and
// deltas), reading the textures u_state, u_train_x, u_train_y:
//   MLP_R_LOAD(base)             parameters and moments from state texels base ..;
//   MLP_R_PICK(k)                p, m, v = parameter vec4 k and its moments (k not a literal);
//   MLP_R_ZERO                   the gradient to 0;
//   MLP_R_INPUTS(row)            the inputs of training row `row`;
//   MLP_R_FORWARD                every layer's units;
//   MLP_R_OUTPUT(row)            the output deltas of d/dy mean((y - t)^2) over the minibatch,
//                                adding the squared errors to `loss` and finiteness to `ok`;
//   MLP_R_BACKWARD               the deltas of every hidden layer (and `ok`);
//   MLP_R_ACCUMULATE             this sample's share of every parameter's gradient;
//   MLP_R_ADAM                   adam_at(k, live) for every parameter vec4.
gl::Defines per_net_step_defines(const MlpSpec& spec, int batch);

}  // namespace sn::nn

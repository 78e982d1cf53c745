// How one network architecture becomes GLSL: the #defines that specialise the shared mlp shaders
// (shaders/include/mlp/*.glsl, mlp_train.comp, mlp_eval.comp, mlp_shade.frag) to its widths,
// depth, activations and colour space, and the parameter layout those shaders read.
//
// The shaders read parameters as vec4s: on llvmpipe every storage-buffer or shared-memory access
// costs a loop over the SIMD lanes whatever its width, so four floats per access is four times
// cheaper. Their layout ("padded") is the flat layout of nn/mlp_spec.h with every weight row and
// every layer's bias vector padded with zeros to whole vec4s; pack_padded / unpack_padded convert.
// Units (one sample's activations of every layer, inputs first) are padded the same way.
//
// Layers are listed as an X-macro of runs (consecutive layers of one shape share their code, a
// loop over the run), with literal widths and offsets: the loops inside a layer have constant
// trip counts the compiler can unroll, the shader's size does not grow with depth, and the
// program cache (keyed by the preprocessed source) holds one program per architecture.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "gl/shader_source.h"
#include "nn/loss.h"
#include "nn/mlp_spec.h"

namespace sn::nn {

inline int chunks4(int n) { return (n + 3) / 4; }

// vec4 offsets in the padded parameter layout.
std::size_t padded_weight_chunk(const MlpSpec& spec, int layer);  // rows of chunks4(in) vec4s
std::size_t padded_bias_chunk(const MlpSpec& spec, int layer);    // chunks4(out) vec4s
std::size_t padded_chunks(const MlpSpec& spec);                   // vec4s of one network
// Where width block i (0 = inputs .. layers() = outputs) starts among a sample's unit vec4s.
std::size_t unit_chunk(const MlpSpec& spec, int i);
std::size_t unit_chunks(const MlpSpec& spec);

// flat (spec.param_count() floats) -> padded (4 * padded_chunks() floats, zeros in the pads).
std::vector<float> pack_padded(const MlpSpec& spec, const float* flat);
void pack_padded(const MlpSpec& spec, const float* flat, float* padded);
// padded -> flat (`flat` holds spec.param_count() floats).
void unpack_padded(const MlpSpec& spec, const float* padded, float* flat);

// Architecture defines shared by every mlp shader:
//   MLP_IN (the first layer's input width: encoded), MLP_RAW_IN (an input row's width),
//   MLP_ENCODED (1 when inputs are encoded: shaders/include/mlp/encoding.glsl), MLP_OUT, MLP_LAYERS, MLP_PARAMS (flat floats), MLP_PQ (padded vec4s), MLP_UQ (unit
//   vec4s), MLP_IN4, MLP_OUT4, MLP_OUT_UQ (first vec4 of the outputs), MLP_MAX_WIDTH, MLP_COLOR,
//   the activations (MLP_ACT_F(z), MLP_ACT_GRAD_Z(z), MLP_ACT_FROM_OUTPUT, MLP_ACT_GRAD_A(a) and
//   the same with MLP_OUT_ACT_ for the output layer: shaders/include/mlp/activation.glsl),
//   and MLP_RUN_TABLE(X) / MLP_RUN_TABLE_REVERSED(X)
//   expanding to X(first_layer, count, in, out, in4, out4, weight_chunk, unit_in, q) per run of
//   equal layers: layer first_layer + k has its weights at vec4 weight_chunk + k*(out*in4 + out4),
//   its biases out*in4 vec4s later, its input units at vec4 unit_in + k*in4 and its outputs in4
//   vec4s after them; q bounds loops over the input vec4s: in4, or `(in4 + u_zero)` to keep a wide
//   layer's loop rolled (shaders declare `uniform int u_zero`). MLP_INNER_RUN_TABLE_REVERSED(X)
//   lists the runs backpropagation passes through (all but the first layer's), last first.
gl::Defines mlp_defines(const MlpSpec& spec);
// The in-memory #includes (gl::Includes) every mlp shader needs with mlp_defines: the GLSL of the network's
// activations from the registry (mlp/act_hidden.glsl, mlp/act_output.glsl) and its encodings
// (mlp/enc_net.glsl, read by mlp/encoding.glsl).
gl::Includes mlp_includes(const MlpSpec& spec);

// Which fused training kernel and where it keeps each array. With `per_net` allowed (a CPU
// renderer) a small network trains in an invocation of its own, everything in registers
// (shaders/mlp_train_per_net.comp, nn/mlp_per_net.h). Otherwise an invocation per sample
// (mlp_train.comp) keeps the arrays in shared memory when they fit, else in a per-network scratch
// region of a storage buffer: moments are the first to move out (touched once per step), then
// the minibatch's activations and deltas, then the parameters.
struct TrainLayout {
  bool per_net = false;  // the per-network kernel (then nothing shared or in scratch)
  bool params_shared = true, moments_shared = true, units_shared = true;
  std::size_t shared_bytes = 0;   // what the kernel declares
  std::size_t scratch_vec4s = 0;  // per network, for the arrays not in shared memory
  std::string describe() const;   // e.g. "params+moments+units in shared memory (31.3 KiB)"
};
TrainLayout plan_train_layout(const MlpSpec& spec, int batch, std::size_t max_shared_bytes, bool per_net);

// mlp_defines plus the kernel's batch and layout (the cache key of its program).
gl::Defines train_defines(const MlpSpec& spec, int batch, const TrainLayout& layout, const Loss& loss);

// mlp_defines plus mlp_eval.comp's mode: "loss" (sums of squared errors per workgroup) or
// "output" (the outputs per row).
// Rows per workgroup: 8 (one SIMD vector of llvmpipe) unless their units do not fit in shared memory.
int eval_local_size(const MlpSpec& spec, std::size_t max_shared_bytes);
// In loss mode the sums are of `loss` (nn/loss.h) instead of squared errors.
gl::Defines eval_defines(const MlpSpec& spec, bool loss_mode, int local_size, const Loss& loss = {});

}  // namespace sn::nn

// How one network architecture becomes GLSL: the #defines that specialise the shared mlp shaders
// (shaders/include/mlp/*.glsl, mlp_train.comp, mlp_eval.comp, mlp_shade.frag) to its widths,
// depth, activations and colour space. Layers are listed as an X-macro with literal widths and
// offsets, so every per-layer loop has a constant trip count the GLSL compiler can unroll, and
// the program cache (keyed by the preprocessed source) holds one program per architecture.
#pragma once
#include <cstddef>
#include <string>

#include "gl/shader_source.h"
#include "nn/mlp_spec.h"

namespace sn::nn {

// Units are every layer's activations of one sample laid end to end: inputs first, outputs last.
// unit_offset(i) is where layer width i (0 = inputs .. layers() = outputs) starts.
std::size_t unit_offset(const MlpSpec& spec, int i);
std::size_t unit_count(const MlpSpec& spec);

// Architecture defines shared by every mlp shader:
//   MLP_IN, MLP_OUT, MLP_LAYERS, MLP_PARAMS, MLP_UNITS, MLP_MAX_WIDTH, MLP_ACT, MLP_OUT_ACT,
//   MLP_SLOPE, MLP_COLOR, and MLP_LAYER_TABLE(X) / MLP_LAYER_TABLE_REVERSED(X) expanding to
//   X(layer, in, out, weight_offset, bias_offset, unit_in, unit_out) per layer, and
//   MLP_INNER_LAYER_TABLE_REVERSED(X) (layers 1.., last first: those backpropagation passes).
gl::Defines mlp_defines(const MlpSpec& spec);

// Where the fused training kernel keeps each array: shared memory when it fits, else a per-network
// scratch region of a storage buffer. Moments are the first to move out (touched once per step),
// then the per-sample activations and deltas, then the weights (read twice per sample).
struct TrainLayout {
  bool params_shared = true, moments_shared = true, units_shared = true;
  std::size_t shared_bytes = 0;   // what the kernel declares
  std::size_t scratch_floats = 0;  // per network, for the arrays not in shared memory
  std::string describe() const;   // e.g. "params+moments+units in shared memory (31.7 KiB)"
};
TrainLayout plan_train_layout(const MlpSpec& spec, int batch, std::size_t max_shared_bytes);

// mlp_defines plus the kernel's batch and layout (the cache key of its program).
gl::Defines train_defines(const MlpSpec& spec, int batch, const TrainLayout& layout);

// mlp_defines plus whether mlp_eval.comp stages the weights in shared memory, and its mode:
// "loss" (sums of squared errors per workgroup) or "output" (the outputs per row).
gl::Defines eval_defines(const MlpSpec& spec, bool loss_mode, std::size_t max_shared_bytes);
constexpr int kEvalLocalSize = 64;

}  // namespace sn::nn

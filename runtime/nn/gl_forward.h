// Networks evaluated over rows of samples in a compute shader (shaders/mlp_eval.comp), one
// invocation per row and one workgroup row per network: `net:forward(samples)`, and the
// validation MSE of every network of a training job without reading outputs back.
#pragma once
#include <cstddef>
#include <memory>
#include <vector>

#include "gl/buffer.h"
#include "nn/loss.h"
#include "nn/mlp.h"

namespace sn::nn {

// `nets` networks of one architecture whose parameters lie in a vec4 buffer in the padded layout
// (nn/mlp_shader.h): network n's start at vec4 `offset + n * stride`.
struct GlParams {
  const gl::Buffer* buffer = nullptr;
  std::size_t offset = 0, stride = 0;
  int nets = 1;
};

// The outputs of every network for `rows` rows of x (rows x spec.inputs floats): `out` receives
// nets x rows x spec.outputs floats. Throws when the buffers are too small, or when the driver's
// loop limit cut a forward pass short (the network is too large for llvmpipe).
void gl_forward(const MlpSpec& spec, const GlParams& params, const gl::Buffer& x, std::size_t rows, gl::Buffer& out);

// Per network: the sum over rows and outputs of (net(x) - y)^2, in double; with `loss`, of that
// loss of net(x) - y (nn/loss.h).
std::vector<double> gl_squared_errors(const MlpSpec& spec, const GlParams& params, const gl::Buffer& x,
                                      const gl::Buffer& y, std::size_t rows, const Loss& loss = {});

// What the first layer of a network with `spec` reads for host rows of raw inputs (rows x
// spec.inputs floats): its encodings evaluated by the GLSL every gl path runs
// (shaders/encoding_check.comp), rows x spec.width(0) floats. The spec must encode something.
std::vector<float> gl_encode(const MlpSpec& spec, const std::vector<float>& x);

// The error for a network whose `pass` ("forward pass", "training step") needs more loop
// iterations than the driver runs per shader invocation (llvmpipe stops at 65,535), with what to
// do: the cpu backend where it has code for the activations, else a smaller network.
std::runtime_error loop_budget_error(const MlpSpec& spec, const std::string& pass);

// One network over host rows (rows x net.spec.inputs floats): its outputs, rows x outputs.
std::vector<float> gl_forward(const Mlp& net, const std::vector<float>& x);
// One network over a buffer of rows: a new float32 buffer of rows x outputs.
std::shared_ptr<gl::Buffer> gl_forward(const Mlp& net, const gl::Buffer& x, std::size_t rows);

}  // namespace sn::nn

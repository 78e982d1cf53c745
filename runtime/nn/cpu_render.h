// CPU inference over a G-buffer: the fragment path's twin (nn/mlp_render.h) for software
// renderers, where llvmpipe runs the fragment shader one network per SIMD lane at a few hundred
// ns per pixel. This path reads back only the attachments the network reads, gathers the covered
// pixels straight into the cpu trainer's lane layout (nn/cpu_net.h: its kernels and activations,
// eight pixels per register), runs them on every thread across bands of rows, and writes RGB
// from the network's colour space, alpha = coverage, uncovered pixels (0, 0, 0, 0) -- what the
// fragment shader writes, within 1e-5 per channel.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "io/image.h"
#include "nn/mlp.h"
#include "nn/render_inputs.h"
#include "scene/gbuffer.h"

namespace sn::nn {

// Seconds the last cpu_render spent per stage (benchmarks and profiling).
struct CpuRenderTimes {
  double read = 0;     // G-buffer attachments to host memory
  double network = 0;  // gather, forward pass, colour conversion, writing the image
};

// What cpu_render writes into `out` (RGBA): the whole frame with rows top first (an Image as
// everyone reads it), or only g.box() with GL's rows, bottom first (for an upload into a texture
// whose other pixels are cleared).
enum class CpuLayout { image, gl_box };

// Throws unless the cpu kernels can run net `spec`, naming the activation, why and backend = "gl".
void check_cpu_code(const MlpSpec& spec);

// Renders `net` over `g` into `out`, resized to what `layout` asks (reused when it has that size:
// a frame then allocates nothing). `inputs` from render_inputs(net, g, values). Returns how many
// covered pixels came out NaN or infinite. Throws when has_cpu_code(net.spec) is false.
std::size_t cpu_render(const Mlp& net, const scene::GBuffer& g, const RenderInputs& inputs, io::Image& out,
                       CpuLayout layout = CpuLayout::image, CpuRenderTimes* times = nullptr);

// Attachments of a G-buffer on the host, inside its box (RGBA floats, GL's row order): what
// cpu_render reads. Read once, a G-buffer renders any number of networks (nn/image_error.h).
struct GBufferTexels {
  std::vector<std::string> attributes;
  std::vector<std::vector<float>> texels;  // per attribute: box width x height x 4
  const std::vector<float>& of(const std::string& attribute) const;  // throws when it was not read
};
// Reads `attributes` of g: on the thread that holds the GL context.
void read_gbuffer(const scene::GBuffer& g, const std::vector<std::string>& attributes, GBufferTexels& out);
// cpu_render from attachments read before (`texels` holds every one `inputs` names): no GL, so
// on any thread.
std::size_t cpu_render(const Mlp& net, const scene::GBuffer& g, const GBufferTexels& texels, const RenderInputs& inputs,
                       io::Image& out, CpuLayout layout = CpuLayout::image);

// A view's covered pixels with a network's first-layer inputs there, gathered once: every
// network that reads the G-buffer the same way (same_inputs) renders from it without scanning
// and gathering again (nn/render_errors.cpp scores hundreds of networks per view). For
// CpuLayout::image. It holds 8 + 4 x (first-layer inputs) bytes per covered pixel.
struct CoveredInputs {
  std::size_t count = 0;         // covered pixels
  int first = 0;                 // what the first layer reads per pixel (encoded when the net encodes)
  std::vector<uint32_t> dst;     // each covered pixel's place in the image (rows top first)
  std::vector<float> alpha;      // and its coverage
  std::vector<float> x;          // the first layer's inputs in CpuNet::forward_lanes' layout, whole blocks
};
CoveredInputs covered_inputs(const MlpSpec& spec, const scene::GBuffer& g, const GBufferTexels& texels,
                             const RenderInputs& inputs);
// Whether two networks read a G-buffer the same way, so one CoveredInputs serves both.
bool same_inputs(const MlpSpec& a, const RenderInputs& ia, const MlpSpec& b, const RenderInputs& ib);
// cpu_render from gathered inputs: the same image, to the bit.
std::size_t cpu_render(const Mlp& net, const scene::GBuffer& g, const CoveredInputs& covered, io::Image& out);

}  // namespace sn::nn

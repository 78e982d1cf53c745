// A network rendered over a G-buffer, by one of two backends that draw the same image (within
// 1e-5 per channel): "gl", the fragment shader (nn/mlp_render.h), the product on a GPU; "cpu",
// the cpu trainer's SIMD kernels over the covered pixels (nn/cpu_render.h), the fast one on a
// software renderer. "auto" picks and says why.
#pragma once
#include <cstddef>
#include <map>
#include <memory>
#include <string>

#include "io/image.h"
#include "nn/cpu_render.h"
#include "nn/mlp.h"
#include "nn/mlp_render.h"
#include "scene/gbuffer.h"

namespace sn::nn {

enum class RenderBackend { automatic, gl, cpu };
const char* render_backend_name(RenderBackend b);  // "auto", "gl", "cpu"

struct RenderOptions {
  RenderBackend backend = RenderBackend::automatic;
  int frames = 1;  // renders this many times (benchmarks); the image is the last
  WeightBuffer weights = WeightBuffer::automatic;  // gl only
  std::map<std::string, double> values;            // conditions' values (nn/render_inputs.h)
};

struct Rendered {
  io::Image image;  // RGBA float, rows top first, alpha = coverage
  RenderBackend backend = RenderBackend::gl;  // the one that drew it
  std::string reason;                         // why (for "auto": the renderer, or the activation)
  std::size_t nonfinite = 0;                  // covered pixels whose colour is NaN or infinite
  CpuRenderTimes cpu_times;                   // the cpu backend's last frame
};

// "gl" and "cpu" as asked ("cpu" throws for an activation without cpu code, naming it and
// backend = "gl"; "cpu" with weights = storage throws too); "auto": gl for such an activation or
// for weights = storage, else cpu on a software renderer (gl::ContextInfo::software), gl on a
// GPU. `reason` says why.
RenderBackend choose_render_backend(const Mlp& net, const RenderOptions& o, std::string* reason);

// Throws before any work what render_inputs() checks.
Rendered render_network(const std::shared_ptr<const Mlp>& net, const scene::GBuffer& g, const RenderOptions& o = {});
// The same into attachment 0 of `out` (g's size) with no image on the host: what a window shows
// (live mode). gl draws there; cpu uploads the box around the meshes and clears the rest. The
// result's image stays empty; its nonfinite is counted by cpu only (gl would need a read-back).
Rendered render_network(const std::shared_ptr<const Mlp>& net, const scene::GBuffer& g, gl::RenderTarget& out,
                        const RenderOptions& o = {});

}  // namespace sn::nn

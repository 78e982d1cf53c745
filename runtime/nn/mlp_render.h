// Fragment-shader inference: a network as the lighting model of every covered pixel of a
// G-buffer (shaders/mlp_shade.frag over shaders/fullscreen.vert). The shader is specialised per
// architecture and input attributes and cached; the parameters live in a GPU buffer per network
// that is re-uploaded only when the network's version() changed, so a weight edit shows in the
// next render with no recompile.
#pragma once
#include <cstddef>
#include <map>
#include <memory>
#include <string>

#include "gl/render_target.h"
#include "nn/mlp.h"
#include "scene/gbuffer.h"

namespace sn::nn {

// Where the fragment shader reads the parameters: a uniform buffer where they fit (every fragment
// reads the same parameters), or always a storage buffer (for comparison).
enum class WeightBuffer { automatic, storage };

// Draws `net` over `g` into attachment 0 of `out` (same size as g): RGB from the network, alpha
// = coverage, uncovered pixels left as cleared (0, 0, 0, 0). `frames` > 1 draws it that many
// times (for timing). Throws before any GPU work what nn/render_inputs.h checks.
// A conditioned network's condition inputs take their values from `values` (by name), else
// from the network (Condition::value). nn/render.h picks between this and the cpu kernels.
void draw_mlp(const std::shared_ptr<const Mlp>& net, const scene::GBuffer& g, gl::RenderTarget& out, int frames = 1,
              WeightBuffer weights = WeightBuffer::automatic, const std::map<std::string, double>& values = {});

// Parameter uploads so far (tests: an unchanged network is not re-uploaded).
std::size_t mlp_weight_uploads();

}  // namespace sn::nn

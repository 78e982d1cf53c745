// How far networks' renders lie from ground-truth images, as a display shows them: each render
// clamped to [0, 1], then the image MSE over the truth's covered pixels and the masked SSIM, of
// RGB (the unseen-mesh columns of the experiments, scripts/lib/experiment.lua). Many networks
// over the same views in one call: each G-buffer is read back once, its covered pixels' inputs
// gathered once per way networks read them, and the (network, view) pairs run on all threads,
// each pair on one, so every number is the one a single render, clamp, MSE and SSIM give.
#pragma once
#include <cstddef>
#include <memory>
#include <vector>

#include "io/image.h"
#include "nn/mlp.h"
#include "scene/gbuffer.h"

namespace sn::nn {

struct TruthView {
  const scene::GBuffer* gbuffer = nullptr;
  const io::Image* truth = nullptr;  // RGBA, the G-buffer's size; alpha = coverage (the mask)
};

struct RenderError {
  double mse = 0, ssim = 0;
  std::size_t nonfinite = 0;  // covered pixels of the render that came out NaN or infinite
};

// errors[i * views.size() + k]: nets[i] over views[k]. Each network renders with the backend
// net:render's "auto" picks (nn/render.h): the cpu ones together on the threads, a gl one (an
// activation without cpu code, or a GPU) on this thread. Throws before any work when a network
// cannot render a view's G-buffer or a truth is not RGBA of its G-buffer's size.
std::vector<RenderError> render_errors(const std::vector<std::shared_ptr<const Mlp>>& nets,
                                       const std::vector<TruthView>& views);

}  // namespace sn::nn

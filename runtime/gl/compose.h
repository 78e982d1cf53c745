// The views live mode shows besides the network and the ground truth: the absolute-error
// heatmap and the side-by-side panel (truth | network | error). The GPU path (a compute pass
// over two render targets) and its double-precision twin, which the tests hold it to.
#pragma once
#include <array>

#include "gl/render_target.h"
#include "io/figure.h"
#include "io/image.h"

namespace sn::gl {

// One heatmap pixel: e = mean over R, G, B of |network - truth|, u = clamp(e / scale, 0, 1),
// coloured by io::colormap(map, u) as the figures' heatmaps are. A pixel neither image covers
// (alpha <= 0.5 in both) is transparent black; a covered one has alpha 1. A non-finite network
// value shows as magenta (1, 0, 1), so a NaN never passes for a small error.
std::array<double, 4> error_heat(const std::array<double, 4>& network, const std::array<double, 4>& truth,
                                 double scale, io::Colormap map = io::Colormap::inferno);

enum class Layout { error, side };

// Output size for `layout` from panels of w x h: error = w x h, side = 3w x h.
std::array<int, 2> composed_size(Layout layout, int w, int h);

// GPU: writes the composition of attachment 0 of `network` and `truth` (same size) into
// attachment 0 of `out` (size composed_size). Throws naming the sizes when they disagree or
// when scale is not > 0.
void compose(Layout layout, const gl::RenderTarget& network, const gl::RenderTarget& truth, double scale,
             io::Colormap map, gl::RenderTarget& out);

// The twin, on images read back with RenderTarget::read (rows top first).
io::Image compose_reference(Layout layout, const io::Image& network, const io::Image& truth, double scale,
                            io::Colormap map);

}  // namespace sn::gl

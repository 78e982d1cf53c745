// The views live mode shows besides the network and the ground truth, as image work: the
// absolute-error heatmap and the side-by-side panels (truth, network, error). This is the
// double-precision twin; the GPU pass that the window uses (gl/compose.h) is held to it.
#pragma once
#include <array>

#include "io/figure.h"
#include "io/image.h"

namespace sn::io {

// One heatmap pixel: e = mean over R, G, B of |network - truth|, u = clamp(e / scale, 0, 1),
// coloured by io::colormap(map, u) as the figures' heatmaps are. A pixel neither image covers
// (alpha <= 0.5 in both) is transparent black; a covered one has alpha 1. A non-finite network
// value shows as magenta (1, 0, 1), so a NaN never passes for a small error.
std::array<double, 4> error_heat(const std::array<double, 4>& network, const std::array<double, 4>& truth,
                                 double scale, Colormap map = Colormap::inferno);

enum class Layout { error, side };

// Output size for `layout` from panels of w x h: error = w x h; side = 2w x 2h, panels top row
// first: truth | network, then error | (transparent), so four panels of the window's aspect
// fill it.
std::array<int, 2> composed_size(Layout layout, int w, int h);

// Throws naming the sizes when the two panels differ, or when scale is not a finite number > 0.
void check_compose_inputs(int network_w, int network_h, int truth_w, int truth_h, double scale);

// The composition of two RGBA images (rows top first, as RenderTarget::read returns them).
Image compose(Layout layout, const Image& network, const Image& truth, double scale, Colormap map);

}  // namespace sn::io

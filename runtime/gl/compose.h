// Live mode's view composition on the GPU: a compute pass over two render targets that writes
// what io::compose (io/compose.h, the twin the tests hold it to) computes.
#pragma once
#include "gl/render_target.h"
#include "io/compose.h"

namespace sn::gl {

// Writes the composition of attachment 0 of `network` and `truth` (same size) into attachment
// 0 of `out` (size io::composed_size). Throws naming the sizes when they disagree or when scale
// is not > 0.
void compose(io::Layout layout, const gl::RenderTarget& network, const gl::RenderTarget& truth, double scale,
             io::Colormap map, gl::RenderTarget& out);

}  // namespace sn::gl

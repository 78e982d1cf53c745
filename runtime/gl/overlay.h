// Live mode's overlays on the GPU: blends an RGBA image (io/overlay.h) over a render target in
// place, and copies a target so the overlays go on a copy and the picture underneath stays.
#pragma once
#include "gl/render_target.h"
#include "io/image.h"

namespace sn::gl {

// Blends `overlay` (RGBA, rows top first) over attachment 0 of `target` with its top-left
// corner at (x, y) (top-left origin); the parts outside the target are skipped.
void blend_over(RenderTarget& target, const io::Image& overlay, int x, int y);

// Copies attachment 0 of `from` into attachment 0 of `to` (same size; throws otherwise), or,
// given a rectangle of `to` (x, y from the top-left), into it, scaled (linear filtering).
void copy_color(const RenderTarget& from, RenderTarget& to);
void copy_color(const RenderTarget& from, RenderTarget& to, int x, int y, int w, int h);

}  // namespace sn::gl

// Compacting a G-buffer on the GPU: every covered pixel (coverage > 0.5) becomes one sample,
// written by an atomic counter into dense per-attribute buffers, so background pixels are
// never stored, shaded or downloaded (shaders/gather.comp).
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "gl/buffer.h"
#include "scene/gbuffer.h"

namespace sn::scene {

struct Samples {
  std::size_t count = 0;  // covered pixels
  // Pixel index y * width + x of each sample (GL rows: y = 0 is the bottom row). The atomic
  // counter hands out slots in whatever order the GPU runs, so callers sort by this.
  std::shared_ptr<gl::Buffer> pixels;             // uint32, count valid
  std::vector<std::shared_ptr<gl::Buffer>> attributes;  // vec4 per sample, one per G-buffer attribute
};

Samples gather(const GBuffer& g);

// Downloads `count` vec4 of a sample buffer as floats (4 per sample).
std::vector<float> download_vec4(const gl::Buffer& b, std::size_t count);
std::vector<uint32_t> download_pixels(const Samples& s);

}  // namespace sn::scene

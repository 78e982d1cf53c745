// Datasets from scenes: scene -> G-buffer -> covered-pixel samples -> ground truth -> rows.
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "data/dataset.h"
#include "scene/scene.h"
#include "shading/color.h"
#include "shading/lighting_params.h"

namespace sn::data {

// The thesis' dataset size: 64,149 covered pixels split 4:1.
constexpr std::size_t kThesisSamples = 64149;

struct DatasetRequest {
  // G-buffer attributes and varied parameters (`vary`), in network input order.
  std::vector<std::string> inputs = {"normal", "view"};
  shading::LightingParams target;
  shading::ColorSpace color = shading::ColorSpace::rgb;
  std::vector<int> views;  // 0-based; empty = every view of the scene
  std::vector<int> poses;  // 0-based; empty = every pose of the scene
  double split = 0.8;      // share of the samples that train; the rest validate
  uint64_t seed = 1;
  std::size_t samples = kThesisSamples;  // at most this many covered pixels (0 = all of them)
  // Scalar parameters of `target` drawn per row, uniformly over [min, max] (within the
  // parameter's domain), from the row's (pose, view, pixel) and the seed; each is also an input.
  std::vector<InputRange> vary;
};

// Renders, gathers, shades and splits (no cache: see dataset_cache.h). Rows are ordered by
// (pose, view, pixel) before a seeded permutation picks the samples and the split, so the result
// depends on the seed only, not on the GPU's scheduling; only the picked rows are shaded (the
// thesis' 64,149 of the 2.2M covered pixels of Table 4.1's 120 views). A view listed twice puts
// each of its rows in twice. Throws for bad inputs, a split outside
// (0, 1), or views that cover no pixel at all.
std::shared_ptr<Dataset> build_dataset(const scene::Scene& s, const DatasetRequest& r);

// Covered pixels of the last build_dataset, before sampling (for messages and tests).
std::size_t last_covered_pixels();

}  // namespace sn::data

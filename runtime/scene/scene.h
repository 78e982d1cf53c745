// A scene: meshes in world space, the cameras it is seen from, an image size and the light the
// ground truth is shaded with. It renders G-buffers per view and turns them into datasets:
// scene -> G-buffer -> covered-pixel samples -> ground truth -> dataset.
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "nn/dataset.h"
#include "scene/camera.h"
#include "scene/gbuffer.h"
#include "scene/mesh.h"
#include "shading/lighting_params.h"

namespace sn::scene {

// The thesis' dataset size: 64,149 covered pixels split 4:1.
constexpr std::size_t kThesisSamples = 64149;

struct Scene {
  std::vector<std::shared_ptr<Mesh>> meshes;
  int width = 256, height = 256;
  std::vector<Camera> views;
  shading::Light light;

  Bounds bounds() const;  // of every mesh
  std::vector<const Mesh*> mesh_list() const;
  // G-buffer of view `view` (0-based); throws naming the valid range.
  GBuffer gbuffer(int view, const std::vector<std::string>& attributes) const;
};

// `count` cameras on a circle around the bounds' centre at `elevation` degrees, far enough that
// the bounding sphere fits the vertical field of view (`distance` overrides that).
std::vector<Camera> framing_orbit(const Bounds& b, int count = 8, double elevation = 20, double fov_y = 45,
                                  std::optional<double> distance = std::nullopt);

struct DatasetRequest {
  std::vector<std::string> inputs = {"normal", "view"};  // G-buffer attributes, in network input order
  shading::LightingParams target;
  nn::ColorSpace color = nn::ColorSpace::rgb;
  std::vector<int> views;  // 0-based; empty = every view of the scene
  double split = 0.8;      // share of the samples that train; the rest validate
  uint64_t seed = 1;
  std::size_t samples = kThesisSamples;  // at most this many covered pixels (0 = all of them)
};

// Renders, gathers, shades and splits (no cache: see dataset_cache.h). Rows are ordered by
// (view, pixel) before a seeded permutation picks the samples and the split, so the result
// depends on the seed only, not on the GPU's scheduling. Throws for bad inputs, a split outside
// (0, 1), or views that cover no pixel at all.
std::shared_ptr<nn::Dataset> build_dataset(const Scene& s, const DatasetRequest& r);

// Covered pixels of the last build_dataset, before sampling (for messages and tests).
std::size_t last_covered_pixels();

}  // namespace sn::scene

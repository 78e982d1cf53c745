// Datasets cached by content: the key covers the meshes' data (hashed), the cameras, the image
// size, the lighting model and every parameter, the light, the inputs, the colour space, the
// split, the seed, the sample count and the shader sources that produce the numbers. An
// identical request returns the dataset already built and renders nothing; any change builds anew.
#pragma once
#include <cstddef>
#include <memory>
#include <string>

#include "data/build.h"
#include "data/dataset.h"
#include "scene/mesh.h"
#include "scene/scene.h"

namespace sn::data {

// The full key text (readable; hashed into Dataset::key).
std::string dataset_key(const scene::Scene& s, const DatasetRequest& r);
// 64-bit FNV-1a of a mesh's positions, normals, uvs, indices and texture.
uint64_t mesh_content_hash(const scene::Mesh& m);

std::shared_ptr<Dataset> cached_dataset(const scene::Scene& s, const DatasetRequest& r);

struct DatasetStats {
  std::size_t builds = 0;   // datasets rendered and shaded
  std::size_t hits = 0;     // requests answered from the cache
  std::size_t gbuffer_renders = 0;
  std::size_t cached = 0;   // datasets held now
};
DatasetStats dataset_stats();
void clear_dataset_cache();

// The cache keeps the most recently used datasets, at most this many.
constexpr std::size_t kDatasetCacheCapacity = 16;

}  // namespace sn::data

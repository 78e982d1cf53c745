// Datasets cached by content: the key covers the meshes' data (hashed), the cameras, the image
// size, the lighting model and every parameter, the light, the inputs, the colour space, the
// split, the seed, the sample count and the shader sources that produce the numbers. An
// identical request returns the dataset already built and renders nothing; any change builds anew.
#pragma once
#include <cstddef>
#include <functional>
#include <initializer_list>
#include <memory>
#include <string>

#include "data/build.h"
#include "data/dataset.h"
#include "gl/shader_source.h"
#include "scene/mesh.h"
#include "scene/scene.h"

namespace sn::data {

// The full key text (readable; hashed into Dataset::key).
std::string dataset_key(const scene::Scene& s, const DatasetRequest& r);
// 64-bit FNV-1a of a mesh's positions, normals, uvs, indices and texture.
uint64_t mesh_content_hash(const scene::Mesh& m);

std::shared_ptr<Dataset> cached_dataset(const scene::Scene& s, const DatasetRequest& r);

// The one LRU every kind of dataset request shares (scene datasets above, sampled ones in
// data/sample.h): the dataset held under `key` (a full key text), or build()'s, stamped with
// Dataset::key and held. Keys of different kinds must differ in their first line.
std::shared_ptr<Dataset> cached(const std::string& key, const std::function<std::shared_ptr<Dataset>()>& build);
// Hex FNV-1a of these shaders' preprocessed sources (includes expanded; `includes` served from
// memory, e.g. a lighting model's assembly and its GLSL), for keys.
std::string shader_sources_hash(std::initializer_list<const char*> files, const gl::Includes& includes = {});

struct DatasetStats {
  std::size_t builds = 0;   // datasets built (rendered or sampled) and shaded
  std::size_t hits = 0;     // requests answered from the cache
  std::size_t gbuffer_renders = 0;
  std::size_t cached = 0;   // datasets held now
};
DatasetStats dataset_stats();
void clear_dataset_cache();

// The cache keeps the most recently used datasets: at most this many, and at most
// io::Limits::dataset_cache_bytes of rows (by count alone, 16 datasets of 2^24 rows held ~9.6 GB
// after the script had dropped them). The one just built is kept whatever its size.
constexpr std::size_t kDatasetCacheCapacity = 16;
// The bytes of a dataset's rows (inputs and targets, both sets).
std::size_t dataset_bytes(const Dataset& d);

}  // namespace sn::data

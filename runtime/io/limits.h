// The resource limits every loader checks before it asks for memory, and the dataset cache's size (docs/reliability.md,
// "Limits"), one set for the whole process. Each exceeded limit is an error naming the file,
// the quantity and the limit, and how to raise it: sn.limits{...} from Lua (lua/wrap_files.cpp),
// set_limits here.
#pragma once
#include <cstdint>
#include <string>

namespace sn::io {

struct Limits {
  // Files read whole: meshes (.gltf/.glb), datasets (.npy, .csv), checkpoints. 1 GiB.
  std::uint64_t file_bytes = std::uint64_t(1) << 30;
  // GLSL sources (sn.program, #include) and lighting models' GLSL files. 16 MiB.
  std::uint64_t shader_bytes = std::uint64_t(1) << 24;
  // Images loaded (sn.image.load, glTF textures): 2^28 pixels (16384 x 16384; 4 GiB as float
  // RGBA) and 64 channels, checked from the header before any pixel is read.
  std::uint64_t image_pixels = std::uint64_t(1) << 28;
  std::uint64_t image_channels = 64;
  // A glTF scene: its node placements (a node under several parents counts once per place),
  // and the vertices and indices of all its primitives together after placement.
  std::uint64_t node_placements = std::uint64_t(1) << 16;
  std::uint64_t mesh_vertices = std::uint64_t(1) << 26;
  std::uint64_t mesh_indices = std::uint64_t(1) << 28;
  // The rows the dataset cache holds for reuse (data/dataset_cache.h), all its datasets
  // together; the one just built stays whatever its size. 1 GiB.
  std::uint64_t dataset_cache_bytes = std::uint64_t(1) << 30;
};

// The limits in force (a copy: thread-safe).
Limits limits();
void set_limits(const Limits& l);

// " (sn.limits{ NAME = ... } raises it)": the hint every limit error ends with.
std::string raise_hint(const char* name);

}  // namespace sn::io

// glTF 2.0 files in and out: what a file may hold, loading one into a Mesh (every check a
// malformed file could need: accessors, indices, nodes, required extensions, external files
// through io::read_file), saving a Mesh as .glb. The Mesh and its operations: scene/mesh.h.
#pragma once
#include <string>

#include "scene/mesh.h"

namespace sn::scene {

// What a glTF scene may be: nodes nested at most this deep (the walk recurses; no real file
// comes near), placed at most io::limits().node_placements times in all (a node under several
// parents counts once per place), with at most mesh_vertices vertices and mesh_indices indices
// after placement (io/limits.h; sn.limits{...} raises them).
constexpr int kMaxNodeDepth = 256;

// Loads a .gltf or .glb file (told apart by content, not extension): walks the default scene's
// node tree and merges every triangle primitive (triangles, strips, fans; uint8/16/32 or no
// indices) as glTF 2.0 draws it without animation: placed by its node's transform (matrix or TRS;
// normals through the inverse transpose), in the rest shape its default morph weights give, a
// skinned one placed by its joints instead of its node (scene/gltf_deform.h); a primitive without
// normals gets flat ones (3.7.2.1), its triangles' vertices split. Throws "mesh file 'PATH':
// reason" for a missing, truncated or malformed file, an accessor reaching outside its buffer, an
// index out of range, or a file with no triangles. The base-colour texture is decoded when first
// read, and throws then if it cannot be (scene/texture.h).
Mesh load_mesh(const std::string& path);

// Writes `m` as a binary glTF (.glb): positions (with min/max), normals, uvs when present,
// uint32 indices and the base-colour texture as an embedded PNG. Written to a temporary file
// and renamed, so a failure leaves nothing behind.
void save_glb(const Mesh& m, const std::string& path);

}  // namespace sn::scene

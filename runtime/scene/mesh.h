// A triangle mesh on the CPU: what a glTF file or a procedural shape becomes before it is
// drawn. One vertex list (position, normal, uv) and one uint32 index list, all primitives of a
// file merged and already placed in world space by the file's node transforms. Files are read
// and written by scene/gltf.h.
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/texture.h"

namespace sn::scene {

class GpuMesh;

struct Bounds {
  glm::dvec3 min{0.0}, max{0.0};
  glm::dvec3 center() const { return (min + max) * 0.5; }
  glm::dvec3 size() const { return max - min; }
  // Radius of the sphere around center() that holds the box (for framing a camera).
  double radius() const { return glm::length(size()) * 0.5; }
};

struct Mesh {
  std::string name;  // file path, or "sphere", "torus", "plane"
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;  // one per position, unit length
  std::vector<glm::vec2> uvs;      // one per position; zeros when has_uvs is false
  std::vector<std::uint32_t> indices;  // three per triangle, counter-clockwise seen from outside
  // One per position or none: unit xyz perpendicular to the normal, w = +-1 the handedness
  // (bitangent = w cross(normal, tangent)). Empty: generated from the UVs when drawn (tangents.h).
  std::vector<glm::vec4> tangents;
  std::string tangent_source;  // "file" (glTF TANGENT), "analytic", or "" (generated when drawn)
  bool has_normals = false;
  bool has_uvs = false;
  // The texture coordinate sets a file's primitives read ("TEXCOORD_1": the set their
  // base-colour texture names), whether the file has them or not; "" for other meshes.
  std::string uv_sets;
  // Some normals did not come from the file or the shape: a primitive without normals got flat
  // ones; callers tell the user. Zero or non-finite normals a file has are repaired without
  // setting it (the loader's note counts them).
  bool normals_computed = false;
  // What loading the file changed or left out, each a sentence the bindings print as
  // "note: mesh file 'PATH' <note>" (computed normals, indices that make no whole triangle).
  std::vector<std::string> notes;
  Texture base_color;  // the material's base-colour texture, as stored (sRGB); decoded on first read
  Bounds bounds;

  std::size_t vertex_count() const { return positions.size(); }
  std::size_t triangle_count() const { return indices.size() / 3; }

  // The uploaded copy (gpu_mesh.h), made on first draw. Whoever edits the arrays above after a
  // draw resets it so the next draw uploads again.
  mutable std::shared_ptr<GpuMesh> gpu;
};

// Area-weighted vertex normals: each triangle adds its unnormalised face normal (length = twice
// its area) to its three vertices. A vertex no triangle touches (or only degenerate ones) gets
// +Y, so no NaN reaches a shader.
std::vector<glm::vec3> area_weighted_normals(const std::vector<glm::vec3>& positions,
                                             const std::vector<std::uint32_t>& indices);

Bounds compute_bounds(const std::vector<glm::vec3>& positions);

// A copy of `m` with `transform` applied (normals through its inverse transpose; winding
// flipped when it mirrors). Throws for a singular matrix.
Mesh transformed(const Mesh& m, const glm::dmat4& transform);

// Throws naming `m.name` when sizes disagree, an index is out of range or a value is not finite.
void validate(const Mesh& m);

}  // namespace sn::scene

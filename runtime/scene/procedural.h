// Procedural meshes with exact analytic normals and UVs: the shapes tests can check against a
// formula (a sphere's normal is its position over its radius). Y is up; triangles are
// counter-clockwise seen from outside; UV (0,0) is the texture's top-left corner, as in glTF.
#pragma once
#include "scene/mesh.h"

namespace sn::scene {

// Centred at the origin. `segments` divide the longitude (around Y), `rings` the latitude
// (pole to pole); the seam and the poles repeat vertices so every vertex has one UV.
// u = longitude / 2pi, starting at +Z towards +X; v = 0 at the north pole (+Y), 1 at the south.
Mesh sphere(double radius = 1.0, int segments = 64, int rings = 32);

// The ring lies in the XZ plane around Y with radius `major`; the tube has radius `minor`.
// `segments` divide the ring, `sides` the tube. u runs around the ring, v around the tube
// (0 at the outer equator, then upwards).
Mesh torus(double major = 1.0, double minor = 0.25, int segments = 64, int sides = 32);

// A square of edge `size` in the XZ plane at y = 0, facing +Y, split into
// `subdivisions` x `subdivisions` quads. u runs along +X, v along +Z.
Mesh plane(double size = 2.0, int subdivisions = 1);

}  // namespace sn::scene

// A scene: meshes in world space, the cameras it is seen from, an image size and the light the
// ground truth is shaded with. It renders G-buffers per view; data/build.h turns them into
// datasets: scene -> G-buffer -> covered-pixel samples -> ground truth -> dataset.
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "scene/camera.h"
#include "scene/gbuffer.h"
#include "scene/mesh.h"
#include "scene/light.h"

namespace sn::scene {

// A mesh in the scene: `transform` maps its coordinates to world space.
struct PlacedMesh {
  std::shared_ptr<Mesh> mesh;
  glm::dmat4 transform{1.0};
};

struct Scene {
  std::vector<PlacedMesh> meshes;
  // Each pose moves the whole mesh set (world = pose * transform * object); datasets render every
  // pose from every view, so one mesh can show the cameras many sides. Default: one, the identity.
  std::vector<glm::dmat4> poses{glm::dmat4(1.0)};
  int width = 256, height = 256;
  std::vector<Camera> views;
  Light light;

  // World bounds of every mesh in every pose (what framing cameras must hold); exact, from the
  // transformed vertices.
  Bounds bounds() const;
  // Bounds of the meshes before any pose (the centre poses turn about).
  Bounds placed_bounds() const;
  // The draws of pose `pose` (0-based).
  std::vector<MeshDraw> draws(int pose = 0) const;
  // G-buffer of view `view` in pose `pose` (0-based); throws naming the valid ranges.
  GBuffer gbuffer(int view, const std::vector<std::string>& attributes, int pose = 0) const;
};

// `count` cameras on a circle around the bounds' centre at `elevation` degrees, far enough that
// the bounding sphere fits the vertical field of view (`distance` overrides that).
std::vector<Camera> framing_orbit(const Bounds& b, int count = 8, double elevation = 20, double fov_y = 45,
                                  std::optional<double> distance = std::nullopt);

}  // namespace sn::scene

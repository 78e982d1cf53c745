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

struct Scene {
  std::vector<std::shared_ptr<Mesh>> meshes;
  int width = 256, height = 256;
  std::vector<Camera> views;
  Light light;

  Bounds bounds() const;  // of every mesh
  std::vector<const Mesh*> mesh_list() const;
  // G-buffer of view `view` (0-based); throws naming the valid range.
  GBuffer gbuffer(int view, const std::vector<std::string>& attributes) const;
};

// `count` cameras on a circle around the bounds' centre at `elevation` degrees, far enough that
// the bounding sphere fits the vertical field of view (`distance` overrides that).
std::vector<Camera> framing_orbit(const Bounds& b, int count = 8, double elevation = 20, double fov_y = 45,
                                  std::optional<double> distance = std::nullopt);

}  // namespace sn::scene

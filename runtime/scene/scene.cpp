#include "scene/scene.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sn::scene {

Bounds Scene::bounds() const {
  if (meshes.empty()) throw std::invalid_argument("the scene has no mesh");
  Bounds b = meshes[0]->bounds;
  for (const auto& m : meshes) b.min = glm::min(b.min, m->bounds.min), b.max = glm::max(b.max, m->bounds.max);
  return b;
}

std::vector<const Mesh*> Scene::mesh_list() const {
  std::vector<const Mesh*> v;
  for (const auto& m : meshes) v.push_back(m.get());
  return v;
}

GBuffer Scene::gbuffer(int view, const std::vector<std::string>& attributes) const {
  if (view < 0 || view >= int(views.size()))
    throw std::out_of_range("view " + std::to_string(view + 1) + " is outside the scene's views 1.." +
                            std::to_string(views.size()));
  return render_gbuffer(mesh_list(), views[view], width, height, attributes);
}

std::vector<Camera> framing_orbit(const Bounds& b, int count, double elevation, double fov_y,
                                  std::optional<double> distance) {
  double r = std::max(b.radius(), 1e-6);
  double d = distance ? *distance : 1.1 * r / std::sin(0.5 * fov_y * 3.14159265358979323846 / 180.0);
  OrbitOptions o;
  o.count = count;
  o.elevation = elevation;
  o.distance = d;
  o.target = b.center();
  o.fov_y = fov_y;
  o.near = std::max(d - 2 * r, d * 1e-3);
  o.far = d + 2 * r;
  return orbit(o);
}

}  // namespace sn::scene

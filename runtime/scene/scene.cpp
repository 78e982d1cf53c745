#include "scene/scene.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "io/text.h"

namespace sn::scene {

namespace {

void grow(Bounds& b, bool& empty, const Mesh& m, const glm::dmat4& to_world) {
  for (const auto& p : m.positions) {
    const glm::dvec3 w = glm::dvec3(to_world * glm::dvec4(glm::dvec3(p), 1.0));
    b.min = empty ? w : glm::min(b.min, w);
    b.max = empty ? w : glm::max(b.max, w);
    empty = false;
  }
}

}  // namespace

Bounds Scene::placed_bounds() const {
  if (meshes.empty()) throw std::invalid_argument("the scene has no mesh");
  Bounds b;
  bool empty = true;
  for (const auto& m : meshes) grow(b, empty, *m.mesh, m.transform);
  return b;
}

Bounds Scene::bounds() const {
  if (meshes.empty()) throw std::invalid_argument("the scene has no mesh");
  Bounds b;
  bool empty = true;
  for (const auto& pose : poses)
    for (const auto& m : meshes) grow(b, empty, *m.mesh, pose * m.transform);
  return b;
}

std::vector<MeshDraw> Scene::draws(int pose) const {
  if (pose < 0 || pose >= int(poses.size()))
    throw std::out_of_range("pose " + std::to_string(pose + 1) + " is outside the scene's poses 1.." +
                            std::to_string(poses.size()));
  std::vector<MeshDraw> v;
  for (const auto& m : meshes) v.push_back({m.mesh.get(), poses[size_t(pose)] * m.transform});
  return v;
}

GBuffer Scene::gbuffer(int view, const std::vector<std::string>& attributes, int pose) const {
  if (view < 0 || view >= int(views.size()))
    throw std::out_of_range("view " + std::to_string(view + 1) + " is outside the scene's views 1.." +
                            std::to_string(views.size()));
  return render_gbuffer(draws(pose), views[view], width, height, attributes);
}

std::vector<Camera> framing_orbit(const Bounds& b, int count, double elevation, double fov_y,
                                  std::optional<double> distance) {
  check_fov(fov_y);  // before the distance that frames the mesh is computed from it
  // Framed meshes must fit the float arithmetic of the shaders: a smaller one was framed as if
  // its radius were 1e-6 (a blank picture), a larger one put the camera beyond float's range.
  // The advice is a scale baked into the vertices (in double, on the CPU): a distance to match
  // left the camera's near and far planes to a radius of 1e-6 and failed its depth check, and a
  // scene transform puts the scale into the GPU's normal matrix, whose tiny entries underflow.
  if (!distance && !(b.radius() >= 1e-6)) {
    const std::string scale = io::number_text(1 / b.radius());
    throw std::invalid_argument("the meshes are too small to frame: their bounding sphere's radius is " +
                                io::number_text(b.radius()) + ", below 1e-6; scale them up by " + scale +
                                " to a radius of 1: mesh:transformed{ scale = " + scale + " }");
  }
  // A ring given its distance brackets the meshes as they are: their radius clamped to 1e-6 put
  // the far plane 1e-6 away, too far for a near plane by a mesh of 1e-11 (the camera refused it).
  const double least = distance ? std::min(1e-6, *distance * 1e-6) : 1e-6;
  double r = std::max(b.radius(), least);
  double d = distance ? *distance : 1.1 * r / std::sin(0.5 * fov_y * 3.14159265358979323846 / 180.0);
  if (!(glm::length(b.center()) + d + 2 * r <= 1e38))
    throw std::invalid_argument("the meshes are too large to frame: the camera would stand " + io::number_text(d) +
                                " from their centre, where float (the shaders' numbers, up to 3.4e38) runs out; "
                                "scale them down");
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

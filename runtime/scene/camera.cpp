#include "scene/camera.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "io/text.h"

namespace sn::scene {

namespace {

constexpr double kPi = 3.14159265358979323846;

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

void check_fov(double fov_y) {
  if (!(fov_y > 0 && fov_y < 180)) throw std::invalid_argument("camera: fov must be in (0, 180) degrees, got " + io::number_text(fov_y));
}

Camera::Camera(glm::dvec3 eye, glm::dvec3 target, glm::dvec3 up, double fov_y, double aspect, double near,
               double far)
    : eye_(eye), target_(target), up_(up), fov_y_(fov_y), aspect_(aspect), near_(near), far_(far) {
  if (!finite(eye) || !finite(target) || !finite(up)) throw std::invalid_argument("camera: eye, target and up must be finite");
  glm::dvec3 forward = target - eye;
  double dist = glm::length(forward);
  if (!(dist > 0)) throw std::invalid_argument("camera: eye and target are the same point");
  // up nearly parallel to the view direction leaves look-at without a sideways axis
  if (!(glm::length(glm::cross(forward / dist, up)) > 1e-6 * glm::length(up)))
    throw std::invalid_argument("camera: up is parallel to the viewing direction (or zero); pick another up");
  check_fov(fov_y);
  if (!(aspect >= 0 && std::isfinite(aspect)))
    throw std::invalid_argument("camera: aspect must be positive (or left out to follow the target), got " + io::number_text(aspect));
  if (!(near > 0 && std::isfinite(near))) throw std::invalid_argument("camera: near must be > 0, got " + io::number_text(near));
  if (!(far > near && std::isfinite(far)))
    throw std::invalid_argument("camera: far (" + io::number_text(far) + ") must be greater than near (" + io::number_text(near) + ")");
  // A depth is 1 - near / distance, nearly: past near * 2^24 it rounds to 1 in a float depth
  // buffer, fails the depth test against the cleared 1, and the surface vanishes without a word.
  constexpr double kDepthSteps = 16777216.0;  // 2^24
  if (near < far / kDepthSteps)
    throw std::invalid_argument("camera: near (" + io::number_text(near) + ") is too small for far (" + io::number_text(far) +
                                "): depths past about near * 2^24 round to the far plane's and their surfaces vanish; "
                                "near must be at least far / 2^24 = " + io::number_text(far / kDepthSteps));
}

glm::dmat4 Camera::view() const { return glm::lookAt(eye_, target_, up_); }

glm::dmat4 Camera::projection(double aspect) const {
  if (!(aspect > 0 && std::isfinite(aspect))) throw std::invalid_argument("camera: aspect must be positive, got " + io::number_text(aspect));
  return glm::perspective(fov_y_ * kPi / 180.0, aspect, near_, far_);
}

Ray Camera::ray(double x, double y, int width, int height) const {
  if (width < 1 || height < 1) throw std::invalid_argument("camera:ray: image size must be at least 1x1");
  double aspect = aspect_for(width, height);
  // Pixel centre -> normalised device coordinates (y up) -> a view-space direction.
  double ndc_x = (x + 0.5) / width * 2 - 1;
  double ndc_y = 1 - (y + 0.5) / height * 2;
  double t = std::tan(fov_y_ * kPi / 360.0);
  glm::dvec3 dir_view(ndc_x * t * aspect, ndc_y * t, -1.0);
  glm::dmat4 inv_view = glm::inverse(view());
  glm::dvec3 dir = glm::dvec3(inv_view * glm::dvec4(dir_view, 0.0));
  return Ray{eye_, glm::normalize(dir)};
}

std::vector<Camera> orbit(const OrbitOptions& o) {
  if (o.count < 1 || o.count > 100000) throw std::invalid_argument("orbit: count must be 1..100000, got " + std::to_string(o.count));
  if (!(o.elevation > -90 && o.elevation < 90))
    throw std::invalid_argument("orbit: elevation must be in (-90, 90) degrees, got " + io::number_text(o.elevation));
  if (!(o.distance > 0 && std::isfinite(o.distance)))
    throw std::invalid_argument("orbit: distance must be > 0, got " + io::number_text(o.distance));
  std::vector<Camera> cams;
  double e = o.elevation * kPi / 180.0;
  for (int k = 0; k < o.count; ++k) {
    double a = 2 * kPi * k / o.count;
    glm::dvec3 offset(std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a));
    // Near a pole the world's up is (almost) the viewing direction; the direction of rising
    // elevation is what it projects to elsewhere, and is never parallel to it.
    const glm::dvec3 up = std::cos(e) > 1e-3 ? glm::dvec3(0, 1, 0)
                                             : glm::dvec3(-std::sin(e) * std::sin(a), std::cos(e), -std::sin(e) * std::cos(a));
    cams.emplace_back(o.target + o.distance * offset, o.target, up, o.fov_y, o.aspect, o.near, o.far);
  }
  return cams;
}

}  // namespace sn::scene

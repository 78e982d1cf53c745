// A pinhole camera (GLM look-at + perspective, OpenGL conventions: right-handed, looking down
// -Z in view space, clip depth -1..1), kept in double precision so tests can use it as the
// oracle for what the rasteriser should see.
#pragma once
#include <vector>

#include <glm/glm.hpp>

namespace sn::scene {

struct Ray {
  glm::dvec3 origin, direction;  // direction is unit length
};

// Throws unless 0 < fov_y < 180 (degrees): every camera's field of view.
void check_fov(double fov_y);

class Camera {
 public:
  // Throws when eye == target, `up` is parallel to the viewing direction, fov_y is outside
  // (0, 180) degrees, near <= 0, far <= near, or aspect < 0. aspect = 0 means "take the
  // render target's width / height" (see aspect_for).
  Camera(glm::dvec3 eye, glm::dvec3 target, glm::dvec3 up = {0, 1, 0}, double fov_y_degrees = 45,
         double aspect = 0, double near = 0.1, double far = 100);

  const glm::dvec3& eye() const { return eye_; }
  const glm::dvec3& target() const { return target_; }
  const glm::dvec3& up() const { return up_; }
  double fov_y() const { return fov_y_; }  // degrees
  double aspect() const { return aspect_; }  // 0 = follow the target
  double near() const { return near_; }
  double far() const { return far_; }

  // The aspect to render a `width` x `height` image with: the camera's own, if it has one.
  double aspect_for(int width, int height) const { return aspect_ > 0 ? aspect_ : double(width) / height; }

  glm::dmat4 view() const;
  glm::dmat4 projection(double aspect) const;

  // The ray from the eye through the centre of pixel (x, y) of a width x height image, with
  // x, y counted from 0 at the top-left pixel (image rows run top to bottom).
  Ray ray(double x, double y, int width, int height) const;

 private:
  glm::dvec3 eye_, target_, up_;
  double fov_y_, aspect_, near_, far_;
};

struct OrbitOptions {
  int count = 8;
  double elevation = 20;  // degrees above the target's horizontal plane, in (-90, 90)
  double distance = 3;    // from the target
  glm::dvec3 target{0, 0, 0};
  double fov_y = 45, aspect = 0, near = 0.1, far = 100;
};

// `count` cameras evenly spaced around the vertical (Y) axis through the target, all looking at
// it from `distance` at `elevation`; camera k sits at azimuth 360 * k / count degrees, measured
// from +Z towards +X.
std::vector<Camera> orbit(const OrbitOptions& o);

}  // namespace sn::scene

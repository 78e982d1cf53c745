// The light a scene is shaded with: a direction towards the light (world space; made unit length
// here) and a colour. The direction is a parameter of the ground truth, not a network input.
#pragma once
#include <string>

#include <glm/glm.hpp>

namespace sn::scene {

struct Light {
  glm::dvec3 dir = glm::normalize(glm::dvec3(0.5, 0.7, 0.6));  // unit: every model relies on it
  glm::dvec3 color{1.0, 1.0, 1.0};
};
// Throws for a zero-length or non-finite direction or a negative / non-finite colour.
Light make_light(const glm::dvec3& dir, const glm::dvec3& color);
std::string light_key(const Light& l);  // exact text, for cache keys

}  // namespace sn::scene

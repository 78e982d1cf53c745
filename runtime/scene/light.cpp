#include "scene/light.h"

#include <cmath>
#include <stdexcept>

#include "io/text.h"

namespace sn::scene {

namespace {
constexpr double kMaxColor = 1e3;  // finite, so every lighting model's output has a bound
}  // namespace

Light make_light(const glm::dvec3& dir, const glm::dvec3& color) {
  double len = glm::length(dir);
  if (!std::isfinite(len) || len < 1e-12)
    throw std::invalid_argument("light 'dir' must be a non-zero, finite direction towards the light, got " +
                                io::vec3_text(dir));
  for (int c = 0; c < 3; ++c)
    if (!std::isfinite(color[c]) || color[c] < 0 || color[c] > kMaxColor)
      throw std::invalid_argument("light 'color' must lie in [0, " + io::number_text(kMaxColor) +
                                  "] per channel, got " + io::vec3_text(color));
  return Light{dir / len, color};
}

std::string light_key(const Light& l) {
  std::string s = "light";
  for (int c = 0; c < 3; ++c) s += " " + io::exact_text(l.dir[c]);
  for (int c = 0; c < 3; ++c) s += " " + io::exact_text(l.color[c]);
  return s;
}

}  // namespace sn::scene

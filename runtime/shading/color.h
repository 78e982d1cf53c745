// Colour spaces the networks can learn in, in double precision: the CPU twin of
// shaders/include/color.glsl (docs/lighting.md states every definition).
//   RGB  linear RGB with the sRGB / Rec. 709 primaries and the D65 white; no transfer curve is
//        applied anywhere in shadenet (images are stored as computed).
//   HSV  hexcone model: H in [0, 1) (hue / 360 deg, 0 for greys), S, V in [0, 1].
//   XYZ  CIE 1931 XYZ from linear RGB by the sRGB D65 matrix; Y of white = 1.
//   Lab  CIE 1976 L*a*b* against the white RGB (1, 1, 1) (= D65); the network-facing encoding
//        "cie_lab" (alias "cie") scales it to about [0, 1]: (L*/100, (a* + 128)/255, (b* + 128)/255).
#pragma once
#include <string>

#include <glm/glm.hpp>

namespace sn::shading {

enum class ColorSpace { rgb, hsv, cie_xyz, cie_lab };
const char* color_space_name(ColorSpace c);
ColorSpace parse_color_space(const std::string& name);  // "rgb", "hsv", "cie" (= cie_lab), "cie_xyz", "cie_lab"

glm::dvec3 rgb_to_hsv(const glm::dvec3& rgb);
glm::dvec3 hsv_to_rgb(const glm::dvec3& hsv);
glm::dvec3 rgb_to_xyz(const glm::dvec3& rgb);
glm::dvec3 xyz_to_rgb(const glm::dvec3& xyz);
glm::dvec3 xyz_to_lab(const glm::dvec3& xyz);  // L* in [0, 100], a*, b* unscaled
glm::dvec3 lab_to_xyz(const glm::dvec3& lab);
glm::dvec3 lab_to_unit(const glm::dvec3& lab);  // the "cie_lab" scaling
glm::dvec3 unit_to_lab(const glm::dvec3& unit);
glm::dvec3 d65_white();  // XYZ of RGB (1, 1, 1)

// RGB -> the space a network learns in, and back (what a renderer applies to a network's output).
glm::dvec3 encode_color(ColorSpace space, const glm::dvec3& rgb);
glm::dvec3 decode_color(ColorSpace space, const glm::dvec3& c);

}  // namespace sn::shading

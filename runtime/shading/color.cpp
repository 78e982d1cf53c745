#include "shading/color.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sn::shading {

using glm::dvec3;

namespace {

const char* kColors[] = {"rgb", "hsv", "cie_xyz", "cie_lab"};

// Linear sRGB (D65) -> XYZ, IEC 61966-2-1 (as Lindbloom tabulates it); glm is column-major.
const glm::dmat3& rgb_to_xyz_matrix() {
  static const glm::dmat3 m = glm::transpose(glm::dmat3(0.4124564, 0.3575761, 0.1804375,  //
                                                        0.2126729, 0.7151522, 0.0721750,  //
                                                        0.0193339, 0.1191920, 0.9503041));
  return m;
}

constexpr double kDelta = 6.0 / 29.0;

double lab_f(double t) {
  return t > kDelta * kDelta * kDelta ? std::cbrt(t) : t / (3.0 * kDelta * kDelta) + 4.0 / 29.0;
}
double lab_f_inverse(double u) { return u > kDelta ? u * u * u : 3.0 * kDelta * kDelta * (u - 4.0 / 29.0); }

}  // namespace

const char* color_space_name(ColorSpace c) { return kColors[int(c)]; }

ColorSpace parse_color_space(const std::string& name) {
  if (name == "cie") return ColorSpace::cie_lab;
  for (int i = 0; i < 4; ++i)
    if (name == kColors[i]) return ColorSpace(i);
  throw std::invalid_argument("unknown colour space '" + name + "' (valid: rgb, hsv, cie, cie_xyz, cie_lab)");
}

dvec3 rgb_to_hsv(const dvec3& c) {
  double mx = std::max(c.r, std::max(c.g, c.b));
  double mn = std::min(c.r, std::min(c.g, c.b));
  double chroma = mx - mn;
  double h = 0.0;
  if (chroma > 0) {
    if (mx == c.r) {
      h = (c.g - c.b) / chroma;
      if (h < 0) h += 6.0;
      if (h >= 6.0) h = 0.0;  // -1e-17 + 6 rounds to 6: hue 1 is hue 0, and H stays in [0, 1)
    } else if (mx == c.g) {
      h = (c.b - c.r) / chroma + 2.0;
    } else {
      h = (c.r - c.g) / chroma + 4.0;
    }
    h /= 6.0;
  }
  double s = mx > 0 ? chroma / mx : 0.0;
  return {h, s, mx};
}

dvec3 hsv_to_rgb(const dvec3& c) {
  // Branch-free hexcone: each channel is a clamped triangle wave of the hue.
  const dvec3 offset(1.0, 2.0 / 3.0, 1.0 / 3.0);
  dvec3 k;
  for (int i = 0; i < 3; ++i) {
    double x = c.x + offset[i];
    x -= std::floor(x);
    k[i] = std::clamp(std::abs(x * 6.0 - 3.0) - 1.0, 0.0, 1.0);
  }
  return c.z * (dvec3(1.0) + c.y * (k - dvec3(1.0)));
}

dvec3 rgb_to_xyz(const dvec3& rgb) { return rgb_to_xyz_matrix() * rgb; }

dvec3 xyz_to_rgb(const dvec3& xyz) {
  static const glm::dmat3 inv = glm::inverse(rgb_to_xyz_matrix());
  return inv * xyz;
}

dvec3 d65_white() { return rgb_to_xyz(dvec3(1.0)); }

dvec3 xyz_to_lab(const dvec3& xyz) {
  dvec3 w = d65_white();
  double fx = lab_f(xyz.x / w.x), fy = lab_f(xyz.y / w.y), fz = lab_f(xyz.z / w.z);
  return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

dvec3 lab_to_xyz(const dvec3& lab) {
  dvec3 w = d65_white();
  double fy = (lab.x + 16.0) / 116.0;
  double fx = fy + lab.y / 500.0;
  double fz = fy - lab.z / 200.0;
  return {w.x * lab_f_inverse(fx), w.y * lab_f_inverse(fy), w.z * lab_f_inverse(fz)};
}

dvec3 lab_to_unit(const dvec3& lab) { return {lab.x / 100.0, (lab.y + 128.0) / 255.0, (lab.z + 128.0) / 255.0}; }
dvec3 unit_to_lab(const dvec3& u) { return {u.x * 100.0, u.y * 255.0 - 128.0, u.z * 255.0 - 128.0}; }

dvec3 encode_color(ColorSpace space, const dvec3& rgb) {
  switch (space) {
    case ColorSpace::rgb: return rgb;
    case ColorSpace::hsv: return rgb_to_hsv(rgb);
    case ColorSpace::cie_xyz: return rgb_to_xyz(rgb);
    case ColorSpace::cie_lab: return lab_to_unit(xyz_to_lab(rgb_to_xyz(rgb)));
  }
  return rgb;
}

dvec3 decode_color(ColorSpace space, const dvec3& c) {
  switch (space) {
    case ColorSpace::rgb: return c;
    case ColorSpace::hsv: return hsv_to_rgb(c);
    case ColorSpace::cie_xyz: return xyz_to_rgb(c);
    case ColorSpace::cie_lab: return xyz_to_rgb(lab_to_xyz(unit_to_lab(c)));
  }
  return c;
}

}  // namespace sn::shading

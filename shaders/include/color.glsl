// Colour spaces the networks learn in (CPU twin: runtime/shading/color.cpp; definitions in
// docs/lighting.md). RGB is linear with the sRGB / Rec. 709 primaries and the D65 white.
// With COLOR_SPACE defined (0 rgb, 1 hsv, 2 cie_xyz, 3 cie_lab: the order of nn::ColorSpace)
// this also defines color_from_rgb (what a dataset stores) and color_to_rgb (what a renderer
// applies to a network's output).
#define COLOR_RGB 0
#define COLOR_HSV 1
#define COLOR_CIE_XYZ 2
#define COLOR_CIE_LAB 3

// Hexcone HSV: H in [0, 1) (hue / 360 degrees; 0 for greys), S and V in [0, 1].
vec3 rgb_to_hsv(vec3 c) {
  float mx = max(c.r, max(c.g, c.b));
  float mn = min(c.r, min(c.g, c.b));
  float chroma = mx - mn;
  float h = 0.0;
  if (chroma > 0.0) {
    if (mx == c.r) {
      h = (c.g - c.b) / chroma;
      if (h < 0.0) h += 6.0;
      if (h >= 6.0) h = 0.0;  // -1e-7 + 6 rounds to 6: hue 1 is hue 0, and H stays in [0, 1)
    } else if (mx == c.g) {
      h = (c.b - c.r) / chroma + 2.0;
    } else {
      h = (c.r - c.g) / chroma + 4.0;
    }
    h /= 6.0;
  }
  float s = mx > 0.0 ? chroma / mx : 0.0;
  return vec3(h, s, mx);
}

vec3 hsv_to_rgb(vec3 c) {
  // Branch-free: each channel is a clamped triangle wave of the hue.
  vec3 k = clamp(abs(fract(c.xxx + vec3(1.0, 2.0 / 3.0, 1.0 / 3.0)) * 6.0 - 3.0) - 1.0, 0.0, 1.0);
  return c.z * (vec3(1.0) + c.y * (k - vec3(1.0)));
}

// CIE 1931 XYZ from linear sRGB (D65), Y of white = 1. GLSL matrices are column-major: these
// are the transposes of the row-major tables.
const mat3 RGB_TO_XYZ = mat3(0.4124564, 0.2126729, 0.0193339,
                             0.3575761, 0.7151522, 0.1191920,
                             0.1804375, 0.0721750, 0.9503041);
const mat3 XYZ_TO_RGB = mat3(3.2404548360, -0.9692663899, 0.0556434196,
                             -1.5371388501, 1.8760109288, -0.2040258543,
                             -0.4985315469, 0.0415560823, 1.0572251625);
const vec3 D65_WHITE = vec3(0.95047, 1.0000001, 1.08883);  // XYZ of RGB (1, 1, 1)

vec3 rgb_to_xyz(vec3 c) { return RGB_TO_XYZ * c; }
vec3 xyz_to_rgb(vec3 c) { return XYZ_TO_RGB * c; }

// CIE 1976 L*a*b* against D65_WHITE: L* in [0, 100], a*, b* unscaled.
const float LAB_DELTA = 6.0 / 29.0;
float lab_f(float t) {
  return t > LAB_DELTA * LAB_DELTA * LAB_DELTA ? pow(t, 1.0 / 3.0) : t / (3.0 * LAB_DELTA * LAB_DELTA) + 4.0 / 29.0;
}
float lab_f_inverse(float u) { return u > LAB_DELTA ? u * u * u : 3.0 * LAB_DELTA * LAB_DELTA * (u - 4.0 / 29.0); }

vec3 xyz_to_lab(vec3 xyz) {
  vec3 t = xyz / D65_WHITE;
  float fx = lab_f(t.x), fy = lab_f(t.y), fz = lab_f(t.z);
  return vec3(116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz));
}

vec3 lab_to_xyz(vec3 lab) {
  float fy = (lab.x + 16.0) / 116.0;
  float fx = fy + lab.y / 500.0;
  float fz = fy - lab.z / 200.0;
  return D65_WHITE * vec3(lab_f_inverse(fx), lab_f_inverse(fy), lab_f_inverse(fz));
}

// The "cie_lab" encoding a network learns: (L*/100, (a* + 128)/255, (b* + 128)/255), about [0, 1].
vec3 lab_to_unit(vec3 lab) { return vec3(lab.x / 100.0, (lab.y + 128.0) / 255.0, (lab.z + 128.0) / 255.0); }
vec3 unit_to_lab(vec3 u) { return vec3(u.x * 100.0, u.y * 255.0 - 128.0, u.z * 255.0 - 128.0); }

#ifdef COLOR_SPACE
vec3 color_from_rgb(vec3 rgb) {
#if COLOR_SPACE == COLOR_RGB
  return rgb;
#elif COLOR_SPACE == COLOR_HSV
  return rgb_to_hsv(rgb);
#elif COLOR_SPACE == COLOR_CIE_XYZ
  return rgb_to_xyz(rgb);
#elif COLOR_SPACE == COLOR_CIE_LAB
  return lab_to_unit(xyz_to_lab(rgb_to_xyz(rgb)));
#else
#error "unknown COLOR_SPACE (0 rgb, 1 hsv, 2 cie_xyz, 3 cie_lab)"
#endif
}

vec3 color_to_rgb(vec3 c) {
#if COLOR_SPACE == COLOR_RGB
  return c;
#elif COLOR_SPACE == COLOR_HSV
  return hsv_to_rgb(c);
#elif COLOR_SPACE == COLOR_CIE_XYZ
  return xyz_to_rgb(c);
#elif COLOR_SPACE == COLOR_CIE_LAB
  return xyz_to_rgb(lab_to_xyz(unit_to_lab(c)));
#endif
}
#endif

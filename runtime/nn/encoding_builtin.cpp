// The encodings shadenet ships, each registered like a user's definition: GLSL of output j
// (over the input's components x, shaders/include/mlp/encoding.glsl has the helpers they share)
// and its double twin. Output order, per encoding:
//   identity       x_0 .. x_{w-1}
//   frequency      [x_0 .. x_{w-1} when include_input], then per component c, per band
//                  k = 0..n-1: sin(2^k pi x_c), cos(2^k pi x_c) (NeRF's gamma, Mildenhall et al.
//                  2020, in tiny-cuda-nn's order; NeRF's code keeps the raw input, tiny-cuda-nn
//                  does not). The GLSL reduces 2^k x_c modulo 2 exactly before the sine, so high
//                  bands keep float accuracy.
//   oneblob        per component c, per bin i = 0..n-1: the mass over bin i of a Gaussian of
//                  sigma = 1 bin centred at s = (x_c - lo) / (hi - lo) (Mueller et al. 2019,
//                  "Neural importance sampling"): Phi(i + 1 - n s) - Phi(i - n s). No wrap-around
//                  (tiny-cuda-nn wraps, and uses a quartic kernel instead of the Gaussian).
//   sh             real spherical harmonics of the direction (x, y, z) for bands l = 0..n-1,
//                  n^2 outputs, with tiny-cuda-nn's constants, order and signs (Sloan's
//                  "Stupid SH tricks" convention: the (-1)^m Condon-Shortley phase is in). The
//                  direction is used as given (tiny-cuda-nn maps [0, 1]^3 to [-1, 1]^3 first;
//                  shadenet's normal and view are already unit vectors).
//   triangle_wave  [x_0 .. x_{w-1} when include_input], then per component c, per band
//                  k = 0..n-1: 4 |frac(2^(k-1) x_c + k/4) - 1/2| - 1, tiny-cuda-nn's (NRC,
//                  Mueller et al. 2021), with its per-band phase shift k/4.
#include <cmath>

#include "nn/encoding.h"

namespace sn::nn {

namespace {

constexpr double kPi = 3.14159265358979323846;

// After the raw components (include_input): the index among the encoded ones, or -1 when j is
// a raw component.
int past_input(const InputEncoding& e, int j) {
  if (!e.include_input) return j;
  return j < e.width ? -1 : j - e.width;
}

double normal_cdf(double t) { return 0.5 * std::erfc(-t / std::sqrt(2.0)); }

double sh(const double* v, int j) {
  const double x = v[0], y = v[1], z = v[2];
  const double xy = x * y, xz = x * z, yz = y * z, x2 = x * x, y2 = y * y, z2 = z * z;
  switch (j) {
    case 0: return 0.28209479177387814;
    case 1: return -0.48860251190291987 * y;
    case 2: return 0.48860251190291987 * z;
    case 3: return -0.48860251190291987 * x;
    case 4: return 1.0925484305920792 * xy;
    case 5: return -1.0925484305920792 * yz;
    case 6: return 0.94617469575755997 * z2 - 0.31539156525251999;
    case 7: return -1.0925484305920792 * xz;
    case 8: return 0.54627421529603959 * x2 - 0.54627421529603959 * y2;
    case 9: return 0.59004358992664352 * y * (-3.0 * x2 + y2);
    case 10: return 2.8906114426405538 * xy * z;
    case 11: return 0.45704579946446572 * y * (1.0 - 5.0 * z2);
    case 12: return 0.3731763325901154 * z * (5.0 * z2 - 3.0);
    case 13: return 0.45704579946446572 * x * (1.0 - 5.0 * z2);
    case 14: return 1.4453057213202769 * z * (x2 - y2);
    case 15: return 0.59004358992664352 * x * (-x2 + 3.0 * y2);
    default: return 0.0;
  }
}

const char* kShGlsl = R"(float X = x.x, Y = x.y, Z = x.z;
  if (j == 0) return 0.28209479177387814;
  if (j == 1) return -0.48860251190291987 * Y;
  if (j == 2) return 0.48860251190291987 * Z;
  if (j == 3) return -0.48860251190291987 * X;
  if (j == 4) return 1.0925484305920792 * X * Y;
  if (j == 5) return -1.0925484305920792 * Y * Z;
  if (j == 6) return 0.94617469575755997 * Z * Z - 0.31539156525251999;
  if (j == 7) return -1.0925484305920792 * X * Z;
  if (j == 8) return 0.54627421529603959 * (X * X - Y * Y);
  if (j == 9) return 0.59004358992664352 * Y * (-3.0 * X * X + Y * Y);
  if (j == 10) return 2.8906114426405538 * X * Y * Z;
  if (j == 11) return 0.45704579946446572 * Y * (1.0 - 5.0 * Z * Z);
  if (j == 12) return 0.3731763325901154 * Z * (5.0 * Z * Z - 3.0);
  if (j == 13) return 0.45704579946446572 * X * (1.0 - 5.0 * Z * Z);
  if (j == 14) return 1.4453057213202769 * Z * (X * X - Y * Y);
  return 0.59004358992664352 * X * (-X * X + 3.0 * Y * Y);)";

EncodingDef def(const char* name, std::string glsl, std::function<int(int, int, bool)> width,
                std::function<double(const InputEncoding&, const double*, int)> f) {
  EncodingDef d;
  d.name = name;
  d.glsl = std::move(glsl);
  d.out_width = std::move(width);
  d.f = std::move(f);
  d.origin = std::string("built-in encoding ") + name;
  return d;
}

void count(EncodingDef& d, const char* name, int lo, int hi, int dflt) {
  d.count = name;
  d.count_min = lo;
  d.count_max = hi;
  d.count_default = dflt;
}

}  // namespace

std::vector<EncodingDef> builtin_encodings() {
  std::vector<EncodingDef> v;
  v.push_back(def("identity", "return x[j];", [](int w, int, bool) { return w; },
                  [](const InputEncoding&, const double* x, int j) { return x[j]; }));

  v.push_back(def("frequency",
                  "if (keep) { if (j < w) return x[j]; j -= w; }\n"
                  "  int c = j / (2 * n), k = (j / 2) % n;\n"
                  "  float t = x[c] * float(1 << k);\n"
                  "  // t = r + u with r an integer, |u| <= 1/2 (exact in float): sin(pi t) = (-1)^r sin(pi u),\n"
                  "  // cos(pi t) = (-1)^r sin(pi (1/2 - |u|)), so their zeros are exact (pi is not a float:\n"
                  "  // sin(pi * 1.0) was 8.7e-8, which training on a zero input made a weight change).\n"
                  "  float r = floor(t + 0.5), u = t - r;\n"
                  "  float sign = mod(r, 2.0) == 0.0 ? 1.0 : -1.0;\n"
                  "  return sign * sin(SN_ENC_PI * ((j & 1) == 0 ? u : 0.5 - abs(u)));",
                  [](int w, int n, bool keep) { return (keep ? w : 0) + 2 * n * w; },
                  [](const InputEncoding& e, const double* x, int j) {
                    const int k = past_input(e, j);
                    if (k < 0) return x[j];
                    const double t = std::ldexp(x[k / (2 * e.n)], (k / 2) % e.n);
                    return (k & 1) == 0 ? std::sin(kPi * t) : std::cos(kPi * t);
                  }));
  count(v.back(), "bands", 1, 16, 6);
  v.back().has_include_input = true;
  v.back().include_input_default = true;
  v.back().f_row = [](const InputEncoding& e, const double* x, double* out) {
    if (e.include_input)
      for (int c = 0; c < e.width; ++c) *out++ = x[c];
    for (int c = 0; c < e.width; ++c)
      for (int k = 0; k < e.n; ++k) {
        const double t = kPi * std::ldexp(x[c], k);
        *out++ = std::sin(t);
        *out++ = std::cos(t);
      }
  };

  v.push_back(def("oneblob",
                  "int c = j / n, i = j - c * n;\n"
                  "  float u = float(i) - (x[c] - range.x) / (range.y - range.x) * float(n);\n"
                  "  return sn_enc_normal_cdf(u + 1.0) - sn_enc_normal_cdf(u);",
                  [](int w, int n, bool) { return n * w; },
                  [](const InputEncoding& e, const double* x, int j) {
                    const int c = j / e.n, i = j % e.n;
                    const double s = (x[c] - e.lo) / (e.hi - e.lo) * double(e.n);
                    return normal_cdf(double(i) + 1.0 - s) - normal_cdf(double(i) - s);
                  }));
  count(v.back(), "bins", 2, 64, 16);
  v.back().has_range = true;
  v.back().f_row = [](const InputEncoding& e, const double* x, double* out) {
    for (int c = 0; c < e.width; ++c) {
      const double s = (x[c] - e.lo) / (e.hi - e.lo) * double(e.n);
      double left = normal_cdf(0.0 - s);
      for (int i = 0; i < e.n; ++i) {
        const double right = normal_cdf(double(i) + 1.0 - s);
        *out++ = right - left;
        left = right;
      }
    }
  };

  v.push_back(def("sh", kShGlsl, [](int, int n, bool) { return n * n; },
                  [](const InputEncoding&, const double* x, int j) { return sh(x, j); }));
  count(v.back(), "degree", 1, 4, 4);
  v.back().input_width = 3;

  v.push_back(def("triangle_wave",
                  "if (keep) { if (j < w) return x[j]; j -= w; }\n"
                  "  int c = j / n, k = j - c * n;\n"
                  "  float u = x[c] * (0.5 * float(1 << k));\n"
                  "  u -= floor(u);  // exact; the phase shift k/4 is added after, to keep float accuracy\n"
                  "  u += fract(0.25 * float(k));\n"
                  "  return abs(u - floor(u) - 0.5) * 4.0 - 1.0;",
                  [](int w, int n, bool keep) { return (keep ? w : 0) + n * w; },
                  [](const InputEncoding& e, const double* x, int j) {
                    const int k = past_input(e, j);
                    if (k < 0) return x[j];
                    const int band = k % e.n;
                    const double u = std::ldexp(x[k / e.n], band - 1) + 0.25 * band;
                    return std::fabs(u - std::floor(u) - 0.5) * 4.0 - 1.0;
                  }));
  count(v.back(), "bands", 1, 16, 6);
  v.back().has_include_input = true;
  v.back().include_input_default = false;
  return v;
}

}  // namespace sn::nn

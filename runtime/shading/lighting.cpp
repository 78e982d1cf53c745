#include "shading/lighting.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "shading/lighting_params.h"

namespace sn::shading {

using glm::dvec3;

dvec3 safe_normalize(const dvec3& x) {
  double x2 = glm::dot(x, x);
  return x2 >= kMinLength2 ? x / std::sqrt(x2) : dvec3(0.0);
}

double cos_lobe(const dvec3& a, const dvec3& b, double e) {
  double d = glm::dot(a, b), aa = glm::dot(a, a) * glm::dot(b, b);
  if (!(d > 0) || !(aa > kMinLength2)) return e == 0 ? 1.0 : 0.0;
  return std::pow(std::min(d / std::sqrt(aa), 1.0), e);
}

namespace {
double clamp_dot(const dvec3& a, const dvec3& b) { return std::clamp(glm::dot(a, b), -1.0, 1.0); }
}  // namespace

dvec3 phong(const dvec3& n, const dvec3& v, const dvec3& l, const dvec3& color, double ambient, const dvec3& specular,
            double shininess) {
  double nl = clamp_dot(n, l);
  dvec3 diffuse = color * (std::max(nl, 0.0) * (1.0 - ambient) + ambient);
  if (!(nl > 0)) return diffuse;
  dvec3 r = 2.0 * nl * n - l;
  return diffuse + specular * cos_lobe(r, v, shininess);
}

dvec3 blinn_phong(const dvec3& n, const dvec3& v, const dvec3& l, const dvec3& color, double ambient,
                  const dvec3& specular, double shininess) {
  double nl = clamp_dot(n, l);
  dvec3 diffuse = color * (std::max(nl, 0.0) * (1.0 - ambient) + ambient);
  if (!(nl > 0)) return diffuse;
  dvec3 h = safe_normalize(l + v);  // v = -l gives h = 0: no highlight
  return diffuse + specular * cos_lobe(n, h, shininess);
}

double phong_reflectance(const dvec3& n, const dvec3& v, const dvec3& l, double ambient, double specular,
                         double shininess) {
  return phong(n, v, l, dvec3(1.0), ambient, dvec3(specular), shininess).x;
}

double ggx_distribution(const dvec3& n, const dvec3& h, double alpha) {
  // 1 - (n.h)^2 as |n x h|^2 keeps its precision where the lobe peaks (n.h -> 1).
  dvec3 nxh = glm::cross(n, h);
  double nh = glm::dot(n, h);
  double d = glm::dot(nxh, nxh) + nh * nh * alpha * alpha;
  return alpha * alpha / (kPi * std::max(d * d, kMinDenominator));
}

double smith_visibility_nl(double nl, double nv, double alpha) {
  double a2 = alpha * alpha;
  double gv = nl * std::sqrt(nv * nv * (1.0 - a2) + a2);
  double gl = nv * std::sqrt(nl * nl * (1.0 - a2) + a2);
  return 0.5 * nl / std::max(gv + gl, kMinDenominator);
}

dvec3 fresnel_schlick(const dvec3& f0, double vh) {
  double m = 1.0 - std::clamp(vh, 0.0, 1.0);
  double m5 = (m * m) * (m * m) * m;
  return f0 + (dvec3(1.0) - f0) * m5;
}

dvec3 ggx(const dvec3& n, const dvec3& v, const dvec3& l, double roughness, const dvec3& f0, const dvec3& diffuse,
          const dvec3& ambient_light, const dvec3& light_color) {
  dvec3 out = ambient_light * (diffuse + f0);
  double nl = clamp_dot(n, l);
  if (!(nl > 0)) return out;
  dvec3 brdf = diffuse * nl;
  double nv = clamp_dot(n, v);
  dvec3 lv = l + v;
  if (nv > 0 && glm::dot(lv, lv) > kMinLength2) {
    double alpha = std::max(roughness * roughness, kMinAlpha);
    dvec3 h = safe_normalize(lv);
    double d = ggx_distribution(n, h, alpha);
    double vis = smith_visibility_nl(nl, nv, alpha);
    brdf += kPi * d * vis * fresnel_schlick(f0, glm::dot(v, h));
  }
  return out + light_color * brdf;
}

dvec3 toon3(double s, const dvec3& c_a, const dvec3& c_d, const dvec3& c_s, double a, const glm::dvec4& t) {
  if (s < t[0]) return c_a;
  if (s < t[1]) return (1.0 - a) * c_a + a * c_d;
  if (s < t[2]) return c_d;
  if (s < t[3]) return (1.0 - a) * c_d + a * c_s;
  return c_s;
}

dvec3 shade_raw(const LightingParams& p, const Surface& s) { return p.spec().twin(s, p); }

dvec3 shade(const LightingParams& p, const Surface& s) { return glm::clamp(shade_raw(p, s), 0.0, 1.0); }

namespace {
Surface surface_at(const scene::Light& light, const dvec3& n, const dvec3& v, const dvec3& base) {
  Surface s = make_surface(light, n, v);
  s.base_color = base;
  return s;
}
}  // namespace

dvec3 shade_raw(const LightingParams& p, const scene::Light& light, const dvec3& n, const dvec3& v, const dvec3& base) {
  return shade_raw(p, surface_at(light, n, v, base));
}

dvec3 shade(const LightingParams& p, const scene::Light& light, const dvec3& n, const dvec3& v, const dvec3& base) {
  return glm::clamp(shade_raw(p, light, n, v, base), 0.0, 1.0);
}

dvec3 upper_bound(const LightingParams& p, const scene::Light& light) {
  if (p.spec().bound) return p.spec().bound(p, light);
  return dvec3(std::numeric_limits<double>::infinity());
}

bool near_discontinuity(const LightingParams& p, const Surface& s, double eps) {
  if (std::abs(glm::dot(s.n, s.l)) < eps || std::abs(glm::dot(s.n, s.v)) < eps) return true;
  // v = -l: the half vector normalize(l + v) is undefined; float and double may each find a
  // different one, or none.
  dvec3 lv = s.l + s.v;
  if (glm::dot(lv, lv) < eps) return true;
  return p.spec().near_branch && p.spec().near_branch(p, s, eps);
}

bool near_discontinuity(const LightingParams& p, const scene::Light& light, const dvec3& n, const dvec3& v, double eps) {
  return near_discontinuity(p, make_surface(light, n, v), eps);
}

}  // namespace sn::shading

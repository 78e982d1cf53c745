#include "shading/builtin_models.h"

#include <cmath>
#include <stdexcept>

#include "gl/shader_source.h"
#include "shading/lighting.h"
#include "shading/lighting_params.h"

namespace sn::shading {

namespace {

using glm::dvec3;

constexpr double kColorMax = 1e3;  // colours and weights: finite, so every model's output has a bound
constexpr double kExponentMax = 1e6;

// The Phong reflectance the thesis writes (section 2.2): C_p [cos(i)(1 - d) + d] + W cos(s)^n.
std::vector<ParamSpec> phong_params(double shininess, std::array<double, 4> color, double ambient, double specular) {
  return {
      {"color", 3, color, 0, kColorMax, "C_p, the diffuse reflection coefficient (r, g, b)"},
      {"ambient", 1, {ambient}, 0, 1, "d, the share of environmental (ambient) reflection, 0..1"},
      {"specular", 3, {specular, specular, specular}, 0, kColorMax, "W, the specular reflection ratio (r, g, b)"},
      {"shininess", 1, {shininess}, 0, kExponentMax, "n, the specular exponent"},
  };
}

dvec3 phong_bound(const LightingParams& p, const scene::Light& light) {
  return light.color * (p.color("color") + p.color("specular"));  // textures are in [0, 1]
}

LightingModel builtin(const char* name, std::vector<ParamSpec> params) {
  LightingModel m;
  m.name = name;
  m.params = std::move(params);
  m.glsl_path = gl::shader_root() + "/models/" + name + ".glsl";
  m.builtin = true;
  return m;
}

}  // namespace

std::vector<LightingModel> builtin_models() {
  std::vector<LightingModel> out;

  LightingModel phong_m = builtin("phong", phong_params(32, {0.8, 0.8, 0.8}, 0.1, 0.5));
  phong_m.twin = [](const Surface& s, const LightingParams& p) {
    return s.light_color * phong(s.n, s.v, s.l, p.color("color"), p.scalar("ambient"), p.color("specular"),
                                 p.scalar("shininess"));
  };
  phong_m.bound = phong_bound;
  out.push_back(phong_m);

  // Blinn's n.h lobe is about 4x wider than Phong's r.v lobe at the same exponent.
  LightingModel blinn = builtin("blinn_phong", phong_params(128, {0.8, 0.8, 0.8}, 0.1, 0.5));
  blinn.twin = [](const Surface& s, const LightingParams& p) {
    return s.light_color * blinn_phong(s.n, s.v, s.l, p.color("color"), p.scalar("ambient"), p.color("specular"),
                                       p.scalar("shininess"));
  };
  blinn.bound = phong_bound;
  out.push_back(blinn);

  LightingModel ggx_m = builtin(
      "ggx", {
                 {"roughness", 1, {0.3}, 0, 1, "perceptual roughness r; the GGX width is alpha = r^2 (at least 1e-3)"},
                 {"f0", 3, {1.0, 0.71, 0.29}, 0, 1, "F0, Fresnel reflectance at normal incidence (r, g, b); gold by default"},
                 {"diffuse", 3, {0, 0, 0}, 0, 1, "Lambertian albedo (r, g, b); 0 for metals"},
                 {"ambient", 3, {0.1, 0.1, 0.1}, 0, kColorMax, "ambient light (r, g, b), reflected with albedo diffuse + f0"},
             });
  ggx_m.twin = [](const Surface& s, const LightingParams& p) {
    return ggx(s.n, s.v, s.l, p.scalar("roughness"), p.color("f0"), p.color("diffuse"), p.color("ambient"), s.light_color);
  };
  ggx_m.bound = [](const LightingParams& p, const scene::Light& light) {
    // pi D <= 1 / alpha^2, V n.l <= 1 / (2 alpha), F <= 1.
    double alpha = std::max(p.scalar("roughness") * p.scalar("roughness"), kMinAlpha);
    dvec3 rho = p.color("diffuse");
    return p.color("ambient") * (rho + p.color("f0")) + light.color * (rho + dvec3(0.5 / (alpha * alpha * alpha)));
  };
  out.push_back(ggx_m);

  LightingModel toon = builtin(
      "toon3", {
                   {"ambient", 3, {0.12, 0.1, 0.3}, 0, kColorMax, "C_a, colour where the Phong reflectance is lowest"},
                   {"diffuse", 3, {0.85, 0.35, 0.2}, 0, kColorMax, "C_d, colour of the lit middle band"},
                   {"specular", 3, {1.0, 0.95, 0.7}, 0, kColorMax, "C_s, colour of the highlight"},
                   {"a", 1, {0.5}, 0, 1, "blend factor of the two transition bands"},
                   {"thresholds", 4, {0.3, 0.4, 0.9, 1.0}, 0, kExponentMax, "t1 <= t2 <= t3 <= t4 on the Phong reflectance S_p"},
                   {"shininess", 1, {32}, 0, kExponentMax, "n of the Phong reflectance S_p"},
                   {"ambient_weight", 1, {0.1}, 0, 1, "d of the Phong reflectance S_p"},
                   {"specular_weight", 1, {0.5}, 0, kColorMax, "W of the Phong reflectance S_p"},
               });
  auto s_p = [](const Surface& s, const LightingParams& p) {
    return phong_reflectance(s.n, s.v, s.l, p.scalar("ambient_weight"), p.scalar("specular_weight"), p.scalar("shininess"));
  };
  toon.twin = [s_p](const Surface& s, const LightingParams& p) {
    return toon3(s_p(s, p), p.color("ambient"), p.color("diffuse"), p.color("specular"), p.scalar("a"),
                 p.vec4("thresholds"));
  };
  toon.bound = [](const LightingParams& p, const scene::Light&) {
    return glm::max(p.color("ambient"), glm::max(p.color("diffuse"), p.color("specular")));
  };
  toon.check_values = [](const LightingParams& p) {
    glm::dvec4 t = p.vec4("thresholds");
    if (!(t[0] <= t[1] && t[1] <= t[2] && t[2] <= t[3]))
      throw std::invalid_argument("sn.lighting.toon3 parameter 'thresholds' must be in order t1 <= t2 <= t3 <= t4, got " +
                                  values_text({t[0], t[1], t[2], t[3]}, 4));
  };
  toon.near_branch = [s_p](const LightingParams& p, const Surface& s, double eps) {
    double v = s_p(s, p);
    glm::dvec4 t = p.vec4("thresholds");
    for (int k = 0; k < 4; ++k)
      if (std::abs(v - t[k]) < eps) return true;
    return false;
  };
  out.push_back(toon);

  LightingModel textured = builtin("textured_phong", phong_params(32, {1, 1, 1}, 0.2, 0.3));
  textured.attributes = {"base_color"};
  textured.twin = [](const Surface& s, const LightingParams& p) {
    return s.light_color * phong(s.n, s.v, s.l, p.color("color") * glm::clamp(s.base_color, 0.0, 1.0),
                                 p.scalar("ambient"), p.color("specular"), p.scalar("shininess"));
  };
  textured.bound = phong_bound;
  out.push_back(textured);
  return out;
}

}  // namespace sn::shading

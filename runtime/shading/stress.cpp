#include "shading/stress.h"

#include <cmath>

#include "shading/color.h"
#include "shading/lighting.h"
#include "shading/lighting_gpu.h"

namespace sn::shading {

using glm::dvec3;

namespace {

// Two unit vectors completing `a` to an orthonormal frame.
void frame(const dvec3& a, dvec3& t, dvec3& b) {
  dvec3 up = std::abs(a.y) < 0.9 ? dvec3(0, 1, 0) : dvec3(1, 0, 0);
  t = glm::normalize(glm::cross(up, a));
  b = glm::cross(a, t);
}

// A unit vector at cosine `c` from `axis`, at azimuth `phi` around it.
dvec3 at_cosine(const dvec3& axis, double c, double phi) {
  dvec3 t, b;
  frame(axis, t, b);
  double s = std::sqrt(std::max(0.0, 1.0 - c * c));
  return c * axis + s * (std::cos(phi) * t + std::sin(phi) * b);
}

}  // namespace

std::vector<StressSample> adversarial_grid(const scene::Light& light) {
  const dvec3 l = light.dir;
  // Cosines: opposite, below, just below, exactly grazing, just above, grazing-ish, above, aligned.
  const double cosines[] = {-1.0, -0.5, -1e-7, 0.0, 1e-7, 1e-3, 0.5, 0.9999999, 1.0};
  const double azimuths_n[] = {0.0, 2.1};
  const double azimuths_v[] = {0.0, 1.5707963267948966, 3.141592653589793, 4.0};
  // Lengths: zero, denormal-small, tiny, unit, huge.
  const double lengths[] = {0.0, 1e-20, 1e-7, 1.0, 1e7};
  std::vector<std::pair<dvec3, dvec3>> dirs;
  for (double cn : cosines)
    for (double an : azimuths_n) {
      dvec3 n = at_cosine(l, cn, an);
      for (double cv : cosines)
        for (double av : azimuths_v) dirs.push_back({n, at_cosine(n, cv, av)});
      dvec3 r = 2.0 * glm::dot(n, l) * n - l;  // Phong's mirror direction: the peak of the lobe
      for (dvec3 v : {l, -l, r, n, -n, glm::normalize(l + n)}) dirs.push_back({n, v});
    }
  std::vector<StressSample> out;
  out.reserve(dirs.size() * 25);
  const glm::vec3 bases[] = {glm::vec3(0.0f), glm::vec3(0.5f), glm::vec3(1.0f), glm::vec3(1.0f, 0.0f, 0.25f)};
  std::size_t k = 0;
  for (const auto& [n, v] : dirs)
    for (double ln : lengths)
      for (double lv : lengths) out.push_back({glm::vec3(n * ln), glm::vec3(v * lv), bases[k++ % 4]});
  return out;
}

StressResult stress_test(const LightingParams& p, const scene::Light& light) {
  auto grid = adversarial_grid(light);
  std::vector<glm::vec3> n(grid.size()), v(grid.size()), base(grid.size());
  for (std::size_t i = 0; i < grid.size(); ++i) n[i] = grid[i].n, v[i] = grid[i].v, base[i] = grid[i].base;

  StressResult r;
  r.samples = grid.size();
  const dvec3 bound = upper_bound(p, light);
  auto count = [&](StressCounts& c, const dvec3& x) {
    for (int ch = 0; ch < 3; ++ch) {
      if (std::isnan(x[ch])) ++c.nan;
      else if (std::isinf(x[ch])) ++c.inf;
      else if (x[ch] < 0) ++c.negative;
      else if (x[ch] > bound[ch] * (1 + 1e-5) + 1e-6) ++c.over;  // float rounding slack
    }
  };
  auto gpu_raw = evaluate(p, light, n, v, base, shading::ColorSpace::rgb, true);
  for (std::size_t i = 0; i < grid.size(); ++i) {
    count(r.gpu, dvec3(gpu_raw[i]));
    count(r.twin, shade_raw(p, light, dvec3(n[i]), dvec3(v[i]), dvec3(base[i])));
    for (int ch = 0; ch < 3; ++ch)
      if (std::isfinite(gpu_raw[i][ch])) r.max_raw = std::max(r.max_raw, double(gpu_raw[i][ch]));
  }
  const dvec3 white = d65_white();
  for (auto space : {shading::ColorSpace::rgb, shading::ColorSpace::hsv, shading::ColorSpace::cie_xyz, shading::ColorSpace::cie_lab}) {
    auto enc = evaluate(p, light, n, v, base, space, false);
    dvec3 hi = space == shading::ColorSpace::cie_xyz ? white : dvec3(1.0);
    for (const auto& e : enc)
      for (int ch = 0; ch < 3; ++ch) {
        if (!std::isfinite(e[ch])) ++r.encoded_nan;
        else if (e[ch] < -1e-6 || e[ch] > hi[ch] + 1e-5) ++r.encoded_out_of_range;
      }
  }
  return r;
}

StressResult stress_test(const LightingParams& p, const std::vector<scene::Light>& lights) {
  StressResult sum;
  auto add = [](StressCounts& a, const StressCounts& b) {
    a.nan += b.nan, a.inf += b.inf, a.negative += b.negative, a.over += b.over;
  };
  for (const scene::Light& l : lights) {
    StressResult r = stress_test(p, l);
    sum.samples += r.samples;
    add(sum.gpu, r.gpu);
    add(sum.twin, r.twin);
    sum.encoded_nan += r.encoded_nan;
    sum.encoded_out_of_range += r.encoded_out_of_range;
    sum.max_raw = std::max(sum.max_raw, r.max_raw);
  }
  return sum;
}

std::vector<scene::Light> stress_lights() { return {scene::make_light({0.5, 0.7, 0.6}, {1, 1, 1}), scene::make_light({0, 1, 0}, {1, 1, 1})}; }

std::vector<StressCase> stress_cases() {
  using P = std::map<std::string, std::vector<double>>;
  std::vector<StressCase> c;
  auto add = [&](Model m, const std::string& label, const P& values) {
    c.push_back({std::string(model_spec(m).name) + (label.empty() ? "" : " " + label), make_params(m, values)});
  };
  for (Model m : {Model::phong, Model::blinn_phong, Model::textured_phong}) {
    add(m, "", {});
    add(m, "n=0", {{"shininess", {0}}});
    add(m, "n=1e6", {{"shininess", {1e6}}});
    add(m, "d=1 W=1e3", {{"ambient", {1}}, {"specular", {1e3}}});
  }
  add(Model::ggx, "", {});
  add(Model::ggx, "roughness=0", {{"roughness", {0}}});
  add(Model::ggx, "roughness=1e-4", {{"roughness", {1e-4}}});
  add(Model::ggx, "roughness=1", {{"roughness", {1}}});
  add(Model::ggx, "roughness=0 f0=1 diffuse=1", {{"roughness", {0}}, {"f0", {1}}, {"diffuse", {1}}});
  add(Model::toon3, "", {});
  add(Model::toon3, "n=0", {{"shininess", {0}}});
  add(Model::toon3, "n=1e6", {{"shininess", {1e6}}});
  add(Model::toon3, "t1=t2=t3=t4", {{"thresholds", {0.5, 0.5, 0.5, 0.5}}});
  return c;
}

}  // namespace sn::shading

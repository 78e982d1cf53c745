#include "shading/stress.h"

#include <cmath>
#include <limits>

#include "shading/color.h"
#include "shading/lighting.h"
#include "shading/lighting_gpu.h"
#include "shading/lighting_params.h"

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
  // Lengths: zero, denormal-small, tiny, unit, huge (its square overflows float).
  const double lengths[] = {0.0, 1e-20, 1e-7, 1.0, 1e30};
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
  const glm::vec3 uvs[] = {glm::vec3(0.0f), glm::vec3(1.0f, 1.0f, 0.0f), glm::vec3(0.5f, 0.25f, 0.0f), glm::vec3(-3.0f, 7.0f, 0.0f)};
  const glm::vec3 positions[] = {glm::vec3(0.0f), glm::vec3(1e-3f, 0.0f, 0.0f), glm::vec3(1.0f, -1.0f, 0.5f),
                                 glm::vec3(1e3f, 1e3f, -1e3f), glm::vec3(-1.0f)};
  std::size_t k = 0;
  for (const auto& [n, v] : dirs) {
    // A tangent frame around the unit normal at a varying angle; every 5th zero, every 7th along n.
    dvec3 t0, b0;
    frame(n, t0, b0);
    for (double ln : lengths)
      for (double lv : lengths) {
        StressSample x;
        x.n = glm::vec3(n * ln), x.v = glm::vec3(v * lv), x.base = bases[k % 4], x.uv = uvs[k % 4];
        x.position = positions[k % 5], x.world_position = positions[(k + 2) % 5];
        double a = 0.7 * double(k);
        dvec3 t = std::cos(a) * t0 + std::sin(a) * b0;
        if (k % 5 == 0) t = dvec3(0.0);
        else if (k % 7 == 0) t = n;
        x.tangent = glm::vec3(t), x.bitangent = glm::vec3(glm::cross(n, t));
        out.push_back(x);
        ++k;
      }
  }
  return out;
}

HostSamples stress_samples(const std::vector<StressSample>& grid) {
  HostSamples h;
  for (const char* a : {"normal", "view", "base_color", "uv", "position", "world_position", "tangent", "bitangent"})
    h[a].reserve(grid.size());
  for (const auto& x : grid) {
    h["normal"].push_back(x.n), h["view"].push_back(x.v), h["base_color"].push_back(x.base), h["uv"].push_back(x.uv);
    h["position"].push_back(x.position), h["world_position"].push_back(x.world_position);
    h["tangent"].push_back(x.tangent), h["bitangent"].push_back(x.bitangent);
  }
  return h;
}

Surface stress_surface(const StressSample& x, const scene::Light& light, const std::vector<std::string>& attributes) {
  Surface s = make_surface(light, dvec3(x.n), dvec3(x.v));
  for (const std::string& a : attributes) {
    if (a == "base_color") s.base_color = dvec3(x.base);
    else if (a == "uv") s.uv = glm::dvec2(x.uv.x, x.uv.y);
    else if (a == "position") s.position = dvec3(x.position);
    else if (a == "world_position") s.world_position = dvec3(x.world_position);
    else if (a == "tangent") s.tangent = safe_normalize(dvec3(x.tangent));
    else if (a == "bitangent") s.bitangent = safe_normalize(dvec3(x.bitangent));
  }
  return s;
}

namespace {
// Only the attributes the model reads go to the GPU.
HostSamples model_samples(const LightingParams& p, const HostSamples& all) {
  HostSamples h{{"normal", all.at("normal")}, {"view", all.at("view")}};
  for (const auto& a : p.spec().attributes) h[a] = all.at(a);
  return h;
}
}  // namespace

StressResult stress_test(const LightingParams& p, const scene::Light& light) {
  auto grid = adversarial_grid(light);
  const HostSamples in = model_samples(p, stress_samples(grid));

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
  auto gpu_raw = evaluate(p, light, in, shading::ColorSpace::rgb, true);
  for (std::size_t i = 0; i < grid.size(); ++i) {
    count(r.gpu, dvec3(gpu_raw[i]));
    count(r.twin, shade_raw(p, stress_surface(grid[i], light, p.spec().attributes)));
    for (int ch = 0; ch < 3; ++ch)
      if (std::isfinite(gpu_raw[i][ch])) r.max_raw = std::max(r.max_raw, double(gpu_raw[i][ch]));
  }
  const dvec3 white = d65_white();
  for (auto space : {shading::ColorSpace::rgb, shading::ColorSpace::hsv, shading::ColorSpace::cie_xyz, shading::ColorSpace::cie_lab}) {
    auto enc = evaluate(p, light, in, space, false);
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

namespace {
// Everyday points beside the adversarial ones: random unit n and v (xorshift, fixed seed), with
// the other attributes cycling through the grid's values.
std::vector<StressSample> random_grid(const std::vector<StressSample>& grid, std::size_t count) {
  uint64_t x = 0x9e3779b97f4a7c15ull;
  auto unit = [&] {
    for (;;) {
      dvec3 d;
      for (int c = 0; c < 3; ++c) {
        x ^= x << 13, x ^= x >> 7, x ^= x << 17;
        d[c] = double(x >> 11) * 0x1p-53 * 2 - 1;
      }
      double l2 = glm::dot(d, d);
      if (l2 > 1e-4 && l2 <= 1) return d / std::sqrt(l2);
    }
  };
  std::vector<StressSample> out(count);
  for (std::size_t i = 0; i < count; ++i) {
    out[i] = grid[i % grid.size()];
    dvec3 n = unit(), t0, b0;
    frame(n, t0, b0);
    out[i].n = glm::vec3(n), out[i].v = glm::vec3(unit());
    out[i].tangent = glm::vec3(t0), out[i].bitangent = glm::vec3(b0);
  }
  return out;
}
}  // namespace

TwinCheck check_twin(const LightingParams& p, const std::vector<scene::Light>& lights) {
  TwinCheck c;
  for (const scene::Light& light : lights) {
    auto grid = adversarial_grid(light);
    auto everyday = random_grid(grid, 20000);
    grid.insert(grid.end(), everyday.begin(), everyday.end());
    auto gpu = evaluate(p, light, model_samples(p, stress_samples(grid)), shading::ColorSpace::rgb, true);
    for (std::size_t i = 0; i < grid.size(); ++i) {
      Surface s = stress_surface(grid[i], light, p.spec().attributes);
      if (near_discontinuity(p, s, kTwinBranchEps)) {
        ++c.skipped;
        continue;
      }
      dvec3 t = shade_raw(p, s);
      ++c.compared;
      for (int ch = 0; ch < 3; ++ch) {
        double d = std::abs(double(gpu[i][ch]) - t[ch]) / std::max(1.0, std::abs(t[ch]));
        if (!(d <= c.max_difference)) {  // NaN on either side counts as the largest
          c.max_difference = std::isfinite(d) ? d : std::numeric_limits<double>::infinity();
          c.worst = s;
          c.worst_gpu = dvec3(gpu[i]);
          c.worst_twin = t;
        }
      }
    }
  }
  return c;
}

std::vector<scene::Light> stress_lights() { return {scene::make_light({0.5, 0.7, 0.6}, {1, 1, 1}), scene::make_light({0, 1, 0}, {1, 1, 1})}; }

std::vector<StressCase> stress_cases() {
  using P = std::map<std::string, std::vector<double>>;
  std::vector<StressCase> c;
  auto add = [&](const char* m, const std::string& label, const P& values) {
    c.push_back({std::string(m) + (label.empty() ? "" : " " + label), make_params(m, values)});
  };
  for (const char* m : {"phong", "blinn_phong", "textured_phong"}) {
    add(m, "", {});
    add(m, "n=0", {{"shininess", {0}}});
    add(m, "n=1e6", {{"shininess", {1e6}}});
    add(m, "d=1 W=1e3", {{"ambient", {1}}, {"specular", {1e3}}});
  }
  add("ggx", "", {});
  add("ggx", "roughness=0", {{"roughness", {0}}});
  add("ggx", "roughness=1e-4", {{"roughness", {1e-4}}});
  add("ggx", "roughness=1", {{"roughness", {1}}});
  add("ggx", "roughness=0 f0=1 diffuse=1", {{"roughness", {0}}, {"f0", {1}}, {"diffuse", {1}}});
  add("toon3", "", {});
  add("toon3", "n=0", {{"shininess", {0}}});
  add("toon3", "n=1e6", {{"shininess", {1e6}}});
  add("toon3", "t1=t2=t3=t4", {{"thresholds", {0.5, 0.5, 0.5, 0.5}}});
  return c;
}

}  // namespace sn::shading

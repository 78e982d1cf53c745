#include "shading/stress.h"

#include <algorithm>
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

namespace {
// check_twin's points under `light`, every `stride`-th grid point and `random` random pairs, as the
// GPU shades them (raw radiance) and as the twin sees them; those near a branch are left out
// (counted in `skipped`).
struct TwinPoint {
  Surface s;
  dvec3 gpu;
};
std::vector<TwinPoint> twin_points(const LightingParams& p, const scene::Light& light, const TwinPoints& points,
                                   std::size_t& skipped) {
  auto all = adversarial_grid(light);
  std::vector<StressSample> grid;
  for (std::size_t i = 0; i < all.size(); i += std::max<std::size_t>(points.grid_stride, 1)) grid.push_back(all[i]);
  auto everyday = random_grid(all, points.random);
  grid.insert(grid.end(), everyday.begin(), everyday.end());
  auto gpu = evaluate(p, light, model_samples(p, stress_samples(grid)), shading::ColorSpace::rgb, true);
  std::vector<TwinPoint> out;
  out.reserve(grid.size());
  for (std::size_t i = 0; i < grid.size(); ++i) {
    Surface s = stress_surface(grid[i], light, p.spec().attributes);
    if (near_discontinuity(p, s, kTwinBranchEps)) ++skipped;
    else out.push_back({s, dvec3(gpu[i])});
  }
  return out;
}

// |gpu - twin| / max(1, |twin|), the largest over the channels; NaN or Inf on either side is infinite.
double twin_difference(const dvec3& gpu, const dvec3& twin) {
  double worst = 0;
  for (int ch = 0; ch < 3; ++ch) {
    double d = std::abs(gpu[ch] - twin[ch]) / std::max(1.0, std::abs(twin[ch]));
    if (!(d <= worst)) worst = std::isfinite(d) ? d : std::numeric_limits<double>::infinity();
  }
  return worst;
}
}  // namespace

TwinCheck check_twin(const LightingParams& p, const std::vector<scene::Light>& lights, const TwinPoints& points) {
  TwinCheck c;
  for (const scene::Light& light : lights)
    for (const TwinPoint& x : twin_points(p, light, points, c.skipped)) {
      dvec3 t = shade_raw(p, x.s);
      ++c.compared;
      double d = twin_difference(x.gpu, t);
      if (!(d <= c.max_difference)) {
        c.max_difference = d;
        c.worst = x.s;
        c.worst_gpu = x.gpu;
        c.worst_twin = t;
      }
    }
  return c;
}

namespace {
// True when the twin, with n, v or l tilted by kHoldTilt about either axis of its frame or
// stretched by 1 +- kHoldStretch (a float unit vector is a few ulps off unit length), reaches the
// GPU's value in every channel (within the tolerance): the point sits on a branch or a lobe so
// steep that float rounding of the inputs moves the value that far, and the twin is right.
bool within_rounding(const LightingParams& p, const Surface& s, const dvec3& gpu, const dvec3& twin) {
  if (!(std::isfinite(gpu.x) && std::isfinite(gpu.y) && std::isfinite(gpu.z))) return false;
  dvec3 lo = twin, hi = twin;
  for (dvec3 Surface::*axis : {&Surface::n, &Surface::v, &Surface::l}) {
    const dvec3 a = s.*axis;
    if (glm::dot(a, a) < 0.5) continue;  // zero: nothing to tilt
    dvec3 t, b;
    frame(a, t, b);
    for (const dvec3& moved : {glm::normalize(a + kHoldTilt * t), glm::normalize(a - kHoldTilt * t),
                               glm::normalize(a + kHoldTilt * b), glm::normalize(a - kHoldTilt * b),
                               a * (1 + kHoldStretch), a * (1 - kHoldStretch)}) {
      Surface near = s;
      near.*axis = moved;
      const dvec3 y = shade_raw(p, near);
      if (std::isfinite(y.x) && std::isfinite(y.y) && std::isfinite(y.z)) lo = glm::min(lo, y), hi = glm::max(hi, y);
    }
  }
  for (int ch = 0; ch < 3; ++ch) {
    const double slack = kHoldTolerance * std::max(1.0, std::abs(twin[ch]));
    if (!(gpu[ch] >= lo[ch] - slack && gpu[ch] <= hi[ch] + slack)) return false;
  }
  return true;
}
}  // namespace

TwinMismatch hold_twin(const LightingParams& p, const scene::Light& light) {
  std::size_t skipped = 0;
  struct Candidate {
    double difference;
    std::size_t at;
    dvec3 twin;
  };
  const std::vector<TwinPoint> points = twin_points(p, light, kHoldPoints, skipped);
  std::vector<Candidate> over;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const dvec3 t = shade_raw(p, points[i].s);
    const dvec3& g = points[i].gpu;
    const bool finite_gpu = std::isfinite(g.x) && std::isfinite(g.y) && std::isfinite(g.z);
    const bool finite_twin = std::isfinite(t.x) && std::isfinite(t.y) && std::isfinite(t.z);
    if (!finite_gpu && !finite_twin) continue;  // both undefined there: the stress test's to report
    const double d = twin_difference(g, t);
    if (d > kHoldTolerance) over.push_back({d, i, t});
  }
  // The worst first: the first that rounding does not explain is the one to show.
  std::stable_sort(over.begin(), over.end(), [](const Candidate& a, const Candidate& b) { return a.difference > b.difference; });
  for (const Candidate& c : over)
    if (!within_rounding(p, points[c.at].s, points[c.at].gpu, c.twin))
      return {true, points[c.at].s, points[c.at].gpu, c.twin, c.difference};
  return {};
}

std::vector<LightingParams> hold_params(const ModelPtr& m) {
  LightingParams defaults, inner;
  defaults.model = inner.model = m;
  for (const ParamSpec& ps : m->params) {
    defaults.values.push_back(ps.def);
    std::array<double, 4> v = ps.def;
    for (int c = 0; c < ps.components; ++c) v[c] += ((v[c] - ps.min <= ps.max - v[c] ? ps.min : ps.max) - v[c]) / 2;
    inner.values.push_back(v);
  }
  std::vector<LightingParams> out = {defaults};
  if (inner.values == defaults.values) return out;
  try {
    if (m->check_values) m->check_values(inner);
    out.push_back(inner);
  } catch (const std::exception&) {
    // a set its cross-parameter check refuses is one no value can take
  }
  return out;
}

scene::Light hold_light() { return scene::make_light(stress_lights()[0].dir, {1.0, 0.8, 0.6}); }

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

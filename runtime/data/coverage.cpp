#include "data/coverage.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "data/input_layout.h"
#include "scene/gather.h"
#include "scene/gbuffer.h"

namespace sn::data {

namespace {

constexpr double kTwoPi = 6.283185307179586;

// Index of `t` in [0, 1] among `n` equal parts; t = 1 (and rounding just below 0) stays inside.
int part(double t, int n) { return std::clamp(int(std::floor(t * n)), 0, n - 1); }

// Angle in [0, 2pi).
double turn(double y, double x) {
  double a = std::atan2(y, x);
  return a < 0 ? a + kTwoPi : a;
}

bool usable(double len2) { return len2 > 1e-30 && std::isfinite(len2); }

struct Bins {
  int normal = -1, view = -1;
  bool below = false;
};

// Both bins of a row from its normalised normal and view; shared by every path so a dataset and
// the rows measured against it are binned the same way.
Bins bins_of(const BinScheme& s, const double n[3], const double v[3]) {
  Bins b;
  b.normal = part((std::clamp(n[1], -1.0, 1.0) + 1) / 2, s.normal_bands) * s.normal_sectors +
             part(turn(n[2], n[0]) / kTwoPi, s.normal_sectors);
  const double c = n[0] * v[0] + n[1] * v[1] + n[2] * v[2];
  if (!(c > 0)) {
    b.below = true;
    return b;
  }
  // t = reference - (reference . n) n, left unnormalised: atan2 needs only the ratio, and
  // b = n x t has the same length as t.
  double t[3];
  if (std::sqrt(n[0] * n[0] + n[2] * n[2]) >= 1e-6) {
    t[0] = -n[1] * n[0], t[1] = 1 - n[1] * n[1], t[2] = -n[1] * n[2];
  } else {
    t[0] = -n[2] * n[0], t[1] = -n[2] * n[1], t[2] = 1 - n[2] * n[2];
  }
  const double bt[3] = {n[1] * t[2] - n[2] * t[1], n[2] * t[0] - n[0] * t[2], n[0] * t[1] - n[1] * t[0]};
  const double psi = turn(v[0] * bt[0] + v[1] * bt[1] + v[2] * bt[2], v[0] * t[0] + v[1] * t[1] + v[2] * t[2]);
  b.view = part(std::min(c, 1.0), s.view_bands) * s.view_sectors + part(psi / kTwoPi, s.view_sectors);
  return b;
}

// Normalises a 3-vector in place; false when it is zero or not finite. `len2` gets its squared length.
bool normalise(double a[3], double& len2) {
  len2 = a[0] * a[0] + a[1] * a[1] + a[2] * a[2];
  if (!usable(len2)) return false;
  const double inv = 1 / std::sqrt(len2);
  a[0] *= inv, a[1] *= inv, a[2] *= inv;
  return true;
}

// Calls f(bins, n) for every valid row; returns the invalid rows, counts the non-unit ones.
template <class F>
std::size_t each_row(const BinScheme& s, const std::vector<DirectionRows>& rows, std::size_t* non_unit, F&& f) {
  std::size_t invalid = 0;
  for (const DirectionRows& r : rows)
    for (std::size_t i = 0; i < r.rows; ++i) {
      const float* pn = r.normal + i * r.stride;
      const float* pv = r.view + i * r.stride;
      double n[3] = {pn[0], pn[1], pn[2]}, v[3] = {pv[0], pv[1], pv[2]};
      double ln, lv;
      if (!normalise(n, ln) || !normalise(v, lv)) {
        ++invalid;
        continue;
      }
      if (non_unit && (std::fabs(std::sqrt(ln) - 1) > 1e-3 || std::fabs(std::sqrt(lv) - 1) > 1e-3)) ++*non_unit;
      f(bins_of(s, n, v), n);
    }
  return invalid;
}

}  // namespace

void BinScheme::check() const {
  const std::pair<const char*, int> parts[] = {{"normal_bands", normal_bands},
                                               {"normal_sectors", normal_sectors},
                                               {"view_bands", view_bands},
                                               {"view_sectors", view_sectors}};
  for (auto [name, n] : parts)
    if (n < 1 || n > kMaxDivisions)
      throw std::invalid_argument(std::string("coverage ") + name + " must be 1.." + std::to_string(kMaxDivisions) +
                                  ", got " + std::to_string(n));
}

std::string BinScheme::text() const {
  return "normal: " + std::to_string(normal_bands) + " bands uniform in y = cos(theta) x " +
         std::to_string(normal_sectors) + " sectors of phi = atan2(z, x); view: " + std::to_string(view_bands) +
         " bands uniform in cos(theta_v) = n.v over (0, 1] x " + std::to_string(view_sectors) +
         " sectors of azimuth from world +y projected onto the tangent plane";
}

int normal_bin(const BinScheme& s, double nx, double ny, double nz) {
  double n[3] = {nx, ny, nz}, len2;
  if (!normalise(n, len2)) return -1;
  const double v[3] = {n[0], n[1], n[2]};
  return bins_of(s, n, v).normal;
}

int view_bin(const BinScheme& s, const double n_in[3], const double v_in[3]) {
  double n[3] = {n_in[0], n_in[1], n_in[2]}, v[3] = {v_in[0], v_in[1], v_in[2]}, len2;
  if (!normalise(n, len2) || !normalise(v, len2)) return -1;
  return bins_of(s, n, v).view;
}

double normal_bin_solid_angle(const BinScheme& s) { return 2 * kTwoPi / s.normal_bins(); }
double view_bin_solid_angle(const BinScheme& s) { return kTwoPi / s.view_bins(); }

std::vector<DirectionRows> dataset_directions(const Dataset& d, const std::string& what) {
  const std::string needed = "coverage needs inputs named \"normal\" and \"view\" (3 numbers each)";
  if (d.input_names.empty())
    throw std::invalid_argument(what + ": the dataset's " + std::to_string(d.inputs) +
                                " inputs have no names; " + needed +
                                " (sn.dataset{ input_names = {\"normal\", \"view\"} } names them)");
  std::string names;
  for (const auto& n : d.input_names) names += (names.empty() ? "\"" : ", \"") + n + "\"";
  names = "{" + names + "}";
  // Columns of each named input, as scene:dataset lays them out (varied parameters included).
  int normal = -1, view = -1;
  std::string why;
  try {
    for (const InputSlot& s : input_layout(d)) {
      if (s.name == "normal") normal = s.offset;
      if (s.name == "view") view = s.offset;
    }
  } catch (const std::exception& e) {
    why = std::string(" (") + e.what() + ")";
  }
  if (normal < 0 || view < 0)
    throw std::invalid_argument(what + ": the dataset's inputs are " + names + " (" + std::to_string(d.inputs) +
                                " numbers); " + needed + ", laid out in the widths of scene attributes" + why);
  std::vector<DirectionRows> out;
  for (const auto* x : {&d.train_x, &d.val_x})
    if (!x->empty())
      out.push_back({x->data() + normal, x->data() + view, std::size_t(d.inputs), x->size() / std::size_t(d.inputs)});
  return out;
}

std::vector<float> scene_directions(const scene::Scene& s) {
  if (s.views.empty()) throw std::invalid_argument("the scene has no views to measure");
  std::vector<float> out;
  for (int pose = 0; pose < int(s.poses.size()); ++pose) for (int v = 0; v < int(s.views.size()); ++v) {
    scene::GBuffer g = s.gbuffer(v, {"normal", "view"}, pose);
    scene::Samples smp = scene::gather(g);
    if (smp.count == 0) continue;
    const std::vector<float> n = scene::download_vec4(*smp.attributes[0], smp.count);
    const std::vector<float> w = scene::download_vec4(*smp.attributes[1], smp.count);
    const std::size_t base = out.size();
    out.resize(base + smp.count * 6);
    for (std::size_t i = 0; i < smp.count; ++i)
      for (int c = 0; c < 3; ++c) {
        out[base + i * 6 + c] = n[i * 4 + c];
        out[base + i * 6 + 3 + c] = w[i * 4 + c];
      }
  }
  if (out.empty())
    throw std::invalid_argument("the scene covers no pixel in " +
                                (s.views.size() == 1 ? std::string("its one view")
                                                     : "any of its " + std::to_string(s.views.size()) + " views") +
                                ": nothing to measure");
  return out;
}

Histogram histogram(const std::vector<DirectionRows>& rows, const BinScheme& scheme) {
  scheme.check();
  Histogram h;
  h.scheme = scheme;
  h.normal.assign(std::size_t(scheme.normal_bins()), 0);
  h.view.assign(std::size_t(scheme.view_bins()), 0);
  for (const DirectionRows& r : rows) h.rows += r.rows;
  if (h.rows == 0) throw std::invalid_argument("the dataset has no rows");
  h.normal_y_min = 1, h.normal_y_max = -1;
  h.invalid = each_row(scheme, rows, &h.non_unit, [&](const Bins& b, const double* n) {
    ++h.normal[std::size_t(b.normal)];
    if (b.below) ++h.below_horizon;
    else ++h.view[std::size_t(b.view)];
    h.normal_y_min = std::min(h.normal_y_min, n[1]);
    h.normal_y_max = std::max(h.normal_y_max, n[1]);
  });
  if (h.invalid == h.rows) h.normal_y_min = h.normal_y_max = 0;
  return h;
}

std::size_t covered_bins(const std::vector<uint32_t>& counts, int min_count) {
  return std::size_t(std::count_if(counts.begin(), counts.end(), [&](uint32_t c) { return c >= uint32_t(min_count); }));
}

Outside outside(const Histogram& mine, int min_count, const std::vector<DirectionRows>& other) {
  if (min_count < 1) throw std::invalid_argument("coverage min_count must be at least 1");
  const uint32_t m = uint32_t(min_count);
  const bool below_covered = mine.below_horizon >= m;
  std::size_t n_out = 0, v_out = 0, e_out = 0, valid = 0;
  each_row(mine.scheme, other, nullptr, [&](const Bins& b, const double*) {
    ++valid;
    const bool no = mine.normal[std::size_t(b.normal)] < m;
    const bool vo = b.below ? !below_covered : mine.view[std::size_t(b.view)] < m;
    n_out += no, v_out += vo, e_out += no || vo;
  });
  if (valid == 0) throw std::invalid_argument("none of the rows to measure has a usable (non-zero, finite) normal and view");
  Outside o;
  o.rows = valid;
  o.normal = double(n_out) / double(valid);
  o.view = double(v_out) / double(valid);
  o.either = double(e_out) / double(valid);
  return o;
}

}  // namespace sn::data

#include "data/build.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "data/random.h"
#include "gl/buffer.h"
#include "io/text.h"
#include "scene/gather.h"
#include "shading/lighting_gpu.h"
#include "shading/render_truth.h"

namespace sn::data {

namespace {
std::size_t g_last_covered = 0;
}  // namespace

namespace {

bool is_varied(const DatasetRequest& r, const std::string& name) {
  for (const auto& v : r.vary)
    if (v.name == name) return true;
  return false;
}

// The varied parameters: scalar parameters of the target, ranges inside their domains, each an input.
void check_vary(const DatasetRequest& r) {
  std::vector<std::string> names;
  for (const auto& v : r.vary) names.push_back(v.name);
  shading::check_vary(r.target.spec(), names);
  for (const auto& v : r.vary) {
    const auto& ps = *std::find_if(r.target.spec().params.begin(), r.target.spec().params.end(),
                                   [&](const shading::ParamSpec& p) { return p.name == v.name; });
    if (!(v.min <= v.max && v.min >= ps.min && v.max <= ps.max))
      throw std::invalid_argument("vary '" + v.name + "': the range [" + io::number_text(v.min) + ", " +
                                  io::number_text(v.max) + "] must be ordered and inside the parameter's domain [" +
                                  io::number_text(ps.min) + ", " + io::number_text(ps.max) + "]");
    if (std::find(r.inputs.begin(), r.inputs.end(), v.name) == r.inputs.end())
      throw std::invalid_argument("vary '" + v.name + "': list it among the inputs too (e.g. inputs = {\"normal\", "
                                  "\"view\", \"" + v.name + "\"}), or a network cannot tell the rows apart");
  }
}

// Parameter k of the row at (pose, view, pixel): uniform in [min, max], the same on every run.
double varied_value(uint64_t seed, uint64_t key, std::size_t k, const InputRange& v) {
  SplitMix h{seed ^ (key * 0x9E3779B97F4A7C15ull) ^ (uint64_t(k + 1) << 58)};
  h.next();
  return v.min + (v.max - v.min) * h.uniform();
}

}  // namespace

std::shared_ptr<Dataset> build_dataset(const scene::Scene& s, const DatasetRequest& r) {
  std::vector<std::string> gbuffer_inputs;
  for (const auto& a : r.inputs)
    if (!is_varied(r, a)) gbuffer_inputs.push_back(a);
  scene::check_attributes(gbuffer_inputs);
  check_vary(r);
  if (!(r.split > 0 && r.split < 1))
    throw std::invalid_argument("dataset split must lie strictly between 0 and 1 (the training share), got " +
                                io::number_text(r.split));
  std::vector<int> views = r.views;
  if (views.empty()) {
    views.resize(s.views.size());
    std::iota(views.begin(), views.end(), 0);
  }
  if (views.empty()) throw std::invalid_argument("the scene has no views to render a dataset from");
  std::vector<int> poses = r.poses;
  if (poses.empty()) {
    poses.resize(s.poses.size());
    std::iota(poses.begin(), poses.end(), 0);
  }
  // Row order keys hold pose and view in 16 bits each.
  if (s.views.size() > 0xffff || s.poses.size() > 0xffff)
    throw std::invalid_argument("a dataset renders at most 65535 views and 65535 poses");

  // Rasterise what the target reads, then the network inputs it does not.
  std::vector<std::string> attributes = shading::model_attributes(r.target);
  for (const auto& a : gbuffer_inputs)
    if (std::find(attributes.begin(), attributes.end(), a) == attributes.end()) attributes.push_back(a);
  auto index_of = [&](const std::string& a) { return int(std::find(attributes.begin(), attributes.end(), a) - attributes.begin()); };

  std::vector<int> widths;  // columns of each input, looked up once, not per row
  int in_width = 0;
  for (const auto& a : r.inputs) in_width += widths.emplace_back(is_varied(r, a) ? 1 : scene::attribute_width(a));

  // Each distinct (pose, view) rendered once, in key order; a pair listed c times puts each of
  // its rows c times in a row into the order below (as sorting c identical renders would).
  struct ViewRows {
    uint64_t key;  // pose << 48 | view << 32
    int pose, view, copies;
    std::vector<uint32_t> pixels;             // y * width + x, per gathered slot
    std::vector<uint32_t> order;              // the slots by pixel
    std::vector<std::vector<float>> values;   // per attribute: 4 floats per slot
  };
  std::vector<ViewRows> groups;
  for (int pose : poses) for (int v : views)
    groups.push_back({(uint64_t(pose) << 48) | (uint64_t(v) << 32), pose, v, 1, {}, {}, {}});
  std::stable_sort(groups.begin(), groups.end(), [](const ViewRows& a, const ViewRows& b) { return a.key < b.key; });
  std::size_t kept = 0;
  for (std::size_t i = 0; i < groups.size(); ++i) {
    if (kept > 0 && groups[kept - 1].key == groups[i].key) {
      ++groups[kept - 1].copies;
      continue;
    }
    groups[kept++] = groups[i];
  }
  groups.resize(kept);

  // Rasterise and gather every view; only the sampled rows are shaded, below. first[g]: the
  // (pose, view, pixel) order's first row of group g.
  std::vector<std::size_t> first;
  std::size_t covered = 0;
  for (auto& g : groups) {
    first.push_back(covered);
    scene::Samples smp = scene::gather(s.gbuffer(g.view, attributes, g.pose));
    if (smp.count == 0) continue;
    g.pixels = scene::download_pixels(smp);
    for (const auto& a : smp.attributes) g.values.push_back(scene::download_vec4(*a, smp.count));
    // The GPU's slot order is a race; the pixel order is not.
    std::vector<uint64_t> by_pixel(smp.count);
    for (std::size_t i = 0; i < smp.count; ++i) by_pixel[i] = (uint64_t(g.pixels[i]) << 32) | i;
    std::sort(by_pixel.begin(), by_pixel.end());
    g.order.resize(smp.count);
    for (std::size_t i = 0; i < smp.count; ++i) g.order[i] = uint32_t(by_pixel[i]);
    covered += smp.count * std::size_t(g.copies);
  }
  g_last_covered = covered;
  if (covered == 0)
    throw std::invalid_argument("the dataset has no covered pixels: the mesh covers no pixel centre in any camera view (" +
                                std::to_string(views.size()) + (views.size() == 1 ? " view" : " views") +
                                (poses.size() > 1 ? " x " + std::to_string(poses.size()) + " poses" : "") + " of " +
                                std::to_string(s.width) + "x" +
                                std::to_string(s.height) +
                                "): it is outside them, or too small or flat (zero area) to cover a pixel; frame it "
                                "with views = sn.orbit{...} or move the cameras");

  SplitMix rng{r.seed};
  std::vector<std::size_t> perm(covered);
  std::iota(perm.begin(), perm.end(), 0);
  for (std::size_t i = perm.size(); i > 1; --i) std::swap(perm[i - 1], perm[rng.below(i)]);
  std::size_t m = r.samples == 0 ? covered : std::min(r.samples, covered);
  if (m < 2)
    throw std::invalid_argument("dataset: " + std::to_string(m) + " covered pixel" + (m == 1 ? "" : "s") +
                                " cannot be split into training and validation rows");
  const std::size_t n_train = train_rows(r.split, m);

  // The sampled rows: group and slot of each, in sample order.
  struct Pick {
    const ViewRows* g;
    uint32_t slot;
    uint64_t key() const { return g->key | g->pixels[slot]; }
    const float* at(int attribute) const { return g->values[std::size_t(attribute)].data() + std::size_t(slot) * 4; }
  };
  std::vector<Pick> picks(m);
  for (std::size_t j = 0; j < m; ++j) {
    const std::size_t k = std::size_t(std::upper_bound(first.begin(), first.end(), perm[j]) - first.begin()) - 1;
    const ViewRows& g = groups[k];
    picks[j] = {&g, g.order[(perm[j] - first[k]) / std::size_t(g.copies)]};
  }

  // The ground truth of the sampled rows, in one dispatch.
  std::vector<std::unique_ptr<gl::Buffer>> model_buffers;
  shading::SampleBuffers model_in;
  for (const auto& a : shading::model_attributes(r.target)) {
    const int at = index_of(a);
    std::vector<float> column(m * 4);
    for (std::size_t j = 0; j < m; ++j) std::copy_n(picks[j].at(at), 4, column.data() + j * 4);
    auto& b = model_buffers.emplace_back(std::make_unique<gl::Buffer>(gl::ElemType::vec4, m));
    b->upload(column.data(), 0, column.size());
    model_in[a] = b.get();
  }
  // The varied parameters per row, one vec4 each (the shader's lighting_vary).
  std::vector<float> varied;
  std::unique_ptr<gl::Buffer> varied_buffer;
  shading::Varied per_row;
  if (!r.vary.empty()) {
    varied.assign(m * 4, 0.0f);
    for (std::size_t j = 0; j < m; ++j)
      for (std::size_t k = 0; k < r.vary.size(); ++k)
        varied[j * 4 + k] = float(varied_value(r.seed, picks[j].key(), k, r.vary[k]));
    varied_buffer = std::make_unique<gl::Buffer>(gl::ElemType::vec4, m);
    varied_buffer->upload(varied.data(), 0, varied.size());
    for (const auto& x : r.vary) per_row.params.push_back(x.name);
    per_row.values = varied_buffer.get();
  }
  gl::Buffer targets(gl::ElemType::vec4, m);
  shading::evaluate(r.target, s.light, model_in, targets, m, r.color, false, r.vary.empty() ? nullptr : &per_row);
  const auto t = scene::download_vec4(targets, m);
  shading::check_finite_targets(r.target, t, m, [&](std::size_t j) {
    auto vec = [](const float* v) {
      return "(" + io::number_text(v[0]) + ", " + io::number_text(v[1]) + ", " + io::number_text(v[2]) + ")";
    };
    return "normal " + vec(picks[j].at(index_of("normal"))) + ", view " + vec(picks[j].at(index_of("view")));
  });

  auto d = std::make_shared<Dataset>();
  d->inputs = in_width;
  d->outputs = 3;
  d->color = r.color;
  d->input_names = r.inputs;
  d->conditions = r.vary;
  d->train_x.reserve(n_train * std::size_t(in_width)), d->val_x.reserve((m - n_train) * std::size_t(in_width));
  d->train_y.reserve(n_train * 3), d->val_y.reserve((m - n_train) * 3);
  // Where each input's columns come from: a G-buffer attribute, or (-1 - v) varied parameter v.
  std::vector<int> source;
  for (const auto& a : r.inputs) {
    if (!is_varied(r, a)) {
      source.push_back(index_of(a));
      continue;
    }
    int v = 0;
    while (r.vary[std::size_t(v)].name != a) ++v;
    source.push_back(-1 - v);
  }
  for (std::size_t j = 0; j < m; ++j) {
    auto& x = j < n_train ? d->train_x : d->val_x;
    auto& y = j < n_train ? d->train_y : d->val_y;
    for (std::size_t k = 0; k < r.inputs.size(); ++k) {
      if (source[k] >= 0) x.insert(x.end(), picks[j].at(source[k]), picks[j].at(source[k]) + widths[k]);
      else x.push_back(varied[j * 4 + std::size_t(-1 - source[k])]);
    }
    y.insert(y.end(), t.begin() + std::ptrdiff_t(j * 4), t.begin() + std::ptrdiff_t(j * 4 + 3));
  }
  return d;
}

std::size_t last_covered_pixels() { return g_last_covered; }

}  // namespace sn::data

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

  struct Row {
    uint64_t key;  // pose << 48 | view << 32 | pixel
    std::size_t at;
  };
  std::vector<Row> rows;
  std::vector<float> xs, ys;  // per gathered sample: in_width inputs, 3 targets
  for (int pose : poses) for (int v : views) {
    scene::GBuffer g = s.gbuffer(v, attributes, pose);
    scene::Samples smp = scene::gather(g);
    if (smp.count == 0) continue;
    gl::Buffer targets(gl::ElemType::vec4, smp.count);
    auto pixels = scene::download_pixels(smp);
    auto key_of = [&](std::size_t i) { return (uint64_t(pose) << 48) | (uint64_t(v) << 32) | pixels[i]; };
    // The varied parameters per sample, one vec4 each (the shader's lighting_vary).
    std::vector<float> varied;
    std::shared_ptr<gl::Buffer> varied_buffer;
    shading::Varied per_row;
    if (!r.vary.empty()) {
      varied.assign(smp.count * 4, 0.0f);
      for (std::size_t i = 0; i < smp.count; ++i)
        for (std::size_t k = 0; k < r.vary.size(); ++k)
          varied[i * 4 + k] = float(varied_value(r.seed, key_of(i), k, r.vary[k]));
      varied_buffer = std::make_shared<gl::Buffer>(gl::ElemType::vec4, smp.count);
      varied_buffer->upload(varied.data(), 0, varied.size());
      for (const auto& x : r.vary) per_row.params.push_back(x.name);
      per_row.values = varied_buffer.get();
    }
    shading::SampleBuffers model_in;
    for (const auto& a : shading::model_attributes(r.target)) model_in[a] = smp.attributes[index_of(a)].get();
    shading::evaluate(r.target, s.light, model_in, targets, smp.count, r.color, false, r.vary.empty() ? nullptr : &per_row);
    auto t = scene::download_vec4(targets, smp.count);
    std::vector<std::vector<float>> in;  // per input: 4 floats per sample
    for (const auto& a : r.inputs) {
      if (!is_varied(r, a)) {
        in.push_back(scene::download_vec4(*smp.attributes[index_of(a)], smp.count));
        continue;
      }
      std::size_t k = 0;
      while (r.vary[k].name != a) ++k;
      std::vector<float> column(smp.count * 4, 0.0f);
      for (std::size_t i = 0; i < smp.count; ++i) column[i * 4] = varied[i * 4 + k];
      in.push_back(std::move(column));
    }
    std::size_t base = ys.size() / 3;
    for (std::size_t i = 0; i < smp.count; ++i) {
      rows.push_back({key_of(i), base + i});
      for (std::size_t k = 0; k < r.inputs.size(); ++k)
        for (int c = 0; c < widths[k]; ++c) xs.push_back(in[k][i * 4 + c]);
      for (int c = 0; c < 3; ++c) ys.push_back(t[i * 4 + c]);
    }
  }
  g_last_covered = rows.size();
  if (rows.empty())
    throw std::invalid_argument("the dataset has no covered pixels: the mesh is outside every camera view (" +
                                std::to_string(views.size()) + (views.size() == 1 ? " view" : " views") +
                                (poses.size() > 1 ? " x " + std::to_string(poses.size()) + " poses" : "") + " of " +
                                std::to_string(s.width) + "x" +
                                std::to_string(s.height) + "); frame it with views = sn.orbit{...} or move the cameras");

  // The GPU's slot order is a race; (pose, view, pixel) is not.
  std::sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.key < b.key; });
  SplitMix rng{r.seed};
  std::vector<std::size_t> perm(rows.size());
  std::iota(perm.begin(), perm.end(), 0);
  for (std::size_t i = perm.size(); i > 1; --i) std::swap(perm[i - 1], perm[rng.below(i)]);
  std::size_t m = r.samples == 0 ? rows.size() : std::min(r.samples, rows.size());
  std::size_t n_train = std::size_t(std::llround(r.split * double(m)));
  if (n_train == 0 || n_train == m)
    throw std::invalid_argument("dataset: " + std::to_string(m) + " samples split " + io::number_text(r.split) +
                                " leaves no " + (n_train == 0 ? "training" : "validation") + " rows");

  auto d = std::make_shared<Dataset>();
  d->inputs = in_width;
  d->outputs = 3;
  d->color = r.color;
  d->input_names = r.inputs;
  d->conditions = r.vary;
  for (std::size_t j = 0; j < m; ++j) {
    std::size_t at = rows[perm[j]].at;
    auto& x = j < n_train ? d->train_x : d->val_x;
    auto& y = j < n_train ? d->train_y : d->val_y;
    x.insert(x.end(), xs.begin() + at * in_width, xs.begin() + (at + 1) * in_width);
    y.insert(y.end(), ys.begin() + at * 3, ys.begin() + (at + 1) * 3);
  }
  return d;
}

std::size_t last_covered_pixels() { return g_last_covered; }

}  // namespace sn::data

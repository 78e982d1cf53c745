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

std::shared_ptr<Dataset> build_dataset(const scene::Scene& s, const DatasetRequest& r) {
  scene::check_attributes(r.inputs);
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
  for (const auto& a : r.inputs)
    if (std::find(attributes.begin(), attributes.end(), a) == attributes.end()) attributes.push_back(a);
  auto index_of = [&](const std::string& a) { return int(std::find(attributes.begin(), attributes.end(), a) - attributes.begin()); };

  int in_width = 0;
  for (const auto& a : r.inputs) in_width += scene::attribute_width(a);

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
    shading::SampleBuffers model_in;
    for (const auto& a : shading::model_attributes(r.target)) model_in[a] = smp.attributes[index_of(a)].get();
    shading::evaluate(r.target, s.light, model_in, targets, smp.count, r.color);
    auto pixels = scene::download_pixels(smp);
    auto t = scene::download_vec4(targets, smp.count);
    std::vector<std::vector<float>> in;
    for (const auto& a : r.inputs) in.push_back(scene::download_vec4(*smp.attributes[index_of(a)], smp.count));
    std::size_t base = ys.size() / 3;
    for (std::size_t i = 0; i < smp.count; ++i) {
      rows.push_back({(uint64_t(pose) << 48) | (uint64_t(v) << 32) | pixels[i], base + i});
      for (std::size_t k = 0; k < r.inputs.size(); ++k)
        for (int c = 0; c < scene::attribute_width(r.inputs[k]); ++c) xs.push_back(in[k][i * 4 + c]);
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

#include "data/combine.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>
#include <stdexcept>

#include "data/input_layout.h"
#include "data/random.h"
#include "io/hash.h"
#include "io/text.h"

namespace sn::data {

namespace {

// The key of a dataset made from `sources` by `operation` (see combine.h).
std::string derived_key(const char* kind, const std::vector<const Dataset*>& sources, const std::string& operation) {
  io::Fnv1a f;
  for (const Dataset* s : sources) {
    if (s->key.empty()) return "";
    uint64_t n = s->key.size();
    f.bytes(&n, sizeof n);  // length first: {ab}{c} and {a}{bc} differ
    f.text(s->key);
  }
  f.text(operation);
  return std::string(kind) + "-" + io::hex64(f.h);
}

std::shared_ptr<Dataset> empty_like(const Dataset& d) {
  auto out = std::make_shared<Dataset>();
  out->inputs = d.inputs;
  out->outputs = d.outputs;
  out->color = d.color;
  out->input_names = d.input_names;
  out->conditions = d.conditions;
  return out;
}

// Appends row `r` of (x, y) to (X, Y).
inline void copy_row(std::vector<float>& X, std::vector<float>& Y, const std::vector<float>& x,
                     const std::vector<float>& y, std::size_t r, int in, int out) {
  X.insert(X.end(), x.begin() + r * in, x.begin() + (r + 1) * in);
  Y.insert(Y.end(), y.begin() + r * out, y.begin() + (r + 1) * out);
}

std::string set_name(bool train) { return train ? "training" : "validation"; }

}  // namespace

std::shared_ptr<Dataset> concat(const std::vector<const Dataset*>& parts) {
  if (parts.empty()) throw std::invalid_argument("no datasets to concatenate");
  const Dataset& first = *parts[0];
  auto out = empty_like(first);
  std::size_t train_floats = 0, val_floats = 0;
  const std::vector<std::string>* names = nullptr;  // the first part's names that has some
  std::size_t named = 0;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const Dataset& p = *parts[i];
    const std::string at = "dataset " + std::to_string(i + 1), ref = "dataset 1";
    if (p.inputs != first.inputs)
      throw std::invalid_argument(at + " has " + std::to_string(p.inputs) + " inputs, " + ref + " has " + std::to_string(first.inputs));
    if (p.outputs != first.outputs)
      throw std::invalid_argument(at + " has " + std::to_string(p.outputs) + " outputs, " + ref + " has " +
                                  std::to_string(first.outputs));
    if (p.color != first.color)
      throw std::invalid_argument(at + " has colour space " + shading::color_space_name(p.color) + ", " + ref + " has " +
                                  shading::color_space_name(first.color));
    if (!(p.conditions == first.conditions))
      throw std::invalid_argument(at + " varies its parameters differently from " + ref +
                                  " (names and ranges must agree)");
    if (!p.input_names.empty()) {
      if (names && *names != p.input_names)
        throw std::invalid_argument(at + " has inputs {" + name_list(p.input_names) + "}, dataset " + std::to_string(named + 1) +
                                    " has {" + name_list(*names) + "}");
      if (!names) names = &p.input_names, named = i;
    }
    train_floats += p.train_x.size();
    val_floats += p.val_x.size();
  }
  if (names) out->input_names = *names;
  out->train_x.reserve(train_floats);
  out->val_x.reserve(val_floats);
  out->train_y.reserve(train_floats / std::max(first.inputs, 1) * first.outputs);
  out->val_y.reserve(val_floats / std::max(first.inputs, 1) * first.outputs);
  for (const Dataset* p : parts) {
    out->train_x.insert(out->train_x.end(), p->train_x.begin(), p->train_x.end());
    out->train_y.insert(out->train_y.end(), p->train_y.begin(), p->train_y.end());
    out->val_x.insert(out->val_x.end(), p->val_x.begin(), p->val_x.end());
    out->val_y.insert(out->val_y.end(), p->val_y.begin(), p->val_y.end());
  }
  out->key = derived_key("concat", parts, "concat " + std::to_string(parts.size()));
  return out;
}

std::shared_ptr<Dataset> subset(const Dataset& d, const SubsetRequest& r) {
  if (r.count && r.fraction) throw std::invalid_argument("give count or fraction, not both");
  std::string op = "subset";

  // Rows of each set that pass the filter, in order.
  std::vector<uint32_t> keep[2];  // [0] training, [1] validation
  const std::size_t have[2] = {d.train_count(), d.val_count()};
  for (int s = 0; s < 2; ++s) {
    keep[s].resize(have[s]);
    std::iota(keep[s].begin(), keep[s].end(), 0u);
  }
  if (r.where) {
    const RowFilter& w = *r.where;
    if (d.input_names.empty())
      throw std::invalid_argument("where: the dataset has no input names, so it has no input '" + w.input + "'");
    const auto layout = input_layout(d);
    const InputSlot* slot = nullptr;
    for (const auto& s : layout)
      if (s.name == w.input) slot = &s;
    if (!slot)
      throw std::invalid_argument("where: no input '" + w.input + "' (the dataset's inputs: " + name_list(d.input_names) + ")");
    if (w.component < 0 || w.component >= slot->width) {
      std::string letters;
      for (int c = 0; c < slot->width; ++c) letters += std::string(letters.empty() ? "" : ", ") + component_letter(slot->name, c);
      throw std::invalid_argument("where: input '" + slot->name + "' has " + std::to_string(slot->width) + " components (" +
                                  letters + " or 1.." + std::to_string(slot->width) + "), not component " +
                                  std::to_string(w.component + 1));
    }
    if (!(w.min <= w.max))
      throw std::invalid_argument("where: min " + io::number_text(w.min) + " is above max " + io::number_text(w.max));
    const std::string test = w.input + "." + component_letter(w.input, w.component) + " in [" + io::number_text(w.min) +
                             ", " + io::number_text(w.max) + "]";
    const int col = slot->offset + w.component;
    for (int s = 0; s < 2; ++s) {
      const float* x = (s == 0 ? d.train_x : d.val_x).data();
      std::size_t n = 0;
      for (std::size_t i = 0; i < have[s]; ++i) {
        const double v = x[i * d.inputs + col];
        if (v >= w.min && v <= w.max) keep[s][n++] = uint32_t(i);
      }
      keep[s].resize(n);
      if (have[s] > 0 && n == 0)
        throw std::invalid_argument("where keeps no " + set_name(s == 0) + " rows (none of " + std::to_string(have[s]) +
                                    " has " + test + ")");
    }
    op += " where " + w.input + " " + std::to_string(w.component) + " " + io::exact_text(w.min) + " " + io::exact_text(w.max);
  }

  const std::size_t kept[2] = {keep[0].size(), keep[1].size()};
  const std::size_t rows = kept[0] + kept[1];
  const int sets = int(kept[0] > 0) + int(kept[1] > 0);
  std::size_t take[2] = {kept[0], kept[1]};
  if (r.count) {
    const std::size_t c = *r.count;
    const std::string after = r.where ? " kept by where" : "";
    if (c < 1) throw std::invalid_argument("count must be at least 1, got 0");
    if (c > rows)
      throw std::invalid_argument("count " + std::to_string(c) + " is more than the " + std::to_string(rows) + " rows" + after);
    if (int(c) < sets)
      throw std::invalid_argument("count " + std::to_string(c) + " cannot keep a row in both the training and the validation set (at least 2)");
    take[0] = std::size_t(std::llround(double(c) * double(kept[0]) / double(rows)));
    if (kept[0] > 0 && take[0] == 0) take[0] = 1;
    if (kept[1] > 0 && take[0] == c) take[0] = c - 1;
    take[1] = c - take[0];
    op += " count " + std::to_string(c);
  } else if (r.fraction) {
    const double f = *r.fraction;
    if (!(f > 0 && f <= 1)) throw std::invalid_argument("fraction must lie in (0, 1], got " + io::number_text(f));
    for (int s = 0; s < 2; ++s) {
      take[s] = std::min(kept[s], std::size_t(std::llround(f * double(kept[s]))));
      if (kept[s] > 0 && take[s] == 0) take[s] = 1;
    }
    op += " fraction " + io::exact_text(f);
  }

  if (r.seed) {
    // A seeded choice of take[s] rows per set: the first take[s] of a partial Fisher-Yates
    // shuffle, put back in their order.
    SplitMix rng{*r.seed};
    for (int s = 0; s < 2; ++s) {
      auto& k = keep[s];
      for (std::size_t i = 0; i < take[s]; ++i) std::swap(k[i], k[i + rng.below(k.size() - i)]);
      k.resize(take[s]);
      std::sort(k.begin(), k.end());
    }
    op += " seed " + std::to_string(*r.seed);
  } else {
    keep[0].resize(take[0]);
    keep[1].resize(take[1]);
  }

  auto out = empty_like(d);
  for (int s = 0; s < 2; ++s) {
    const bool train = s == 0;
    auto& X = train ? out->train_x : out->val_x;
    auto& Y = train ? out->train_y : out->val_y;
    X.reserve(keep[s].size() * d.inputs);
    Y.reserve(keep[s].size() * d.outputs);
    for (uint32_t i : keep[s]) copy_row(X, Y, train ? d.train_x : d.val_x, train ? d.train_y : d.val_y, i, d.inputs, d.outputs);
  }
  out->key = derived_key("subset", {&d}, op);
  return out;
}

std::shared_ptr<Dataset> resplit(const Dataset& d, double split, uint64_t seed) {
  if (!(split > 0 && split < 1))
    throw std::invalid_argument("split must lie strictly between 0 and 1 (the training share), got " + io::number_text(split));
  const std::size_t nt = d.train_count(), n = nt + d.val_count();
  if (n < 2)
    throw std::invalid_argument(std::to_string(n) + (n == 1 ? " row" : " rows") +
                                " cannot be split into training and validation rows");
  const std::size_t n_train = train_rows(split, n);
  SplitMix rng{seed};
  std::vector<std::size_t> perm(n);
  std::iota(perm.begin(), perm.end(), 0);
  for (std::size_t i = perm.size(); i > 1; --i) std::swap(perm[i - 1], perm[rng.below(i)]);
  auto out = empty_like(d);
  out->train_x.reserve(n_train * d.inputs);
  out->train_y.reserve(n_train * d.outputs);
  out->val_x.reserve((n - n_train) * d.inputs);
  out->val_y.reserve((n - n_train) * d.outputs);
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t r = perm[j];
    const bool from_train = r < nt;
    auto& X = j < n_train ? out->train_x : out->val_x;
    auto& Y = j < n_train ? out->train_y : out->val_y;
    copy_row(X, Y, from_train ? d.train_x : d.val_x, from_train ? d.train_y : d.val_y, from_train ? r : r - nt, d.inputs,
             d.outputs);
  }
  out->key = derived_key("split", {&d}, "split " + io::exact_text(split) + " seed " + std::to_string(seed));
  return out;
}

}  // namespace sn::data

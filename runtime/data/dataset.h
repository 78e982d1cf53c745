// Training data as every backend reads it: covered-pixel samples split into training and
// validation rows. Inputs and targets are row-major floats; targets are already in the colour
// space the networks learn in (`color`).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "shading/color.h"

namespace sn::data {

// An input that is a lighting-model parameter sampled per row over [min, max] (a conditioned
// dataset: one network learns the model over the whole range), not a G-buffer attribute.
struct InputRange {
  std::string name;
  double min = 0, max = 0;
  bool operator==(const InputRange& o) const { return name == o.name && min == o.min && max == o.max; }
};

struct Dataset {
  int inputs = 0, outputs = 0;
  shading::ColorSpace color = shading::ColorSpace::rgb;
  std::vector<float> train_x, train_y;  // train_count() rows
  std::vector<float> val_x, val_y;      // val_count() rows
  std::vector<std::string> input_names;  // e.g. {"normal", "view"}: what a network trained on it reads
  std::vector<InputRange> conditions;    // the input names that are varied parameters (width 1 each)
  std::string key;                       // content key of what produced it (for caching)

  std::size_t train_count() const { return inputs ? train_x.size() / inputs : 0; }
  std::size_t val_count() const { return inputs ? val_x.size() / inputs : 0; }
};

// How many of `rows` rows a split of `split` (in (0, 1]) trains: round(split * rows), but at
// least one row of each set where there are two rows and the split is below 1 (2 rows at 0.8
// rounded to no validation row, and sn.train refused the dataset). Every dataset splits by it.
inline std::size_t train_rows(double split, std::size_t rows) {
  const std::size_t n = std::size_t(std::llround(split * double(rows)));
  const std::size_t most = split < 1 && rows >= 2 ? rows - 1 : rows;
  return n < 1 ? std::min<std::size_t>(1, rows) : n > most ? most : n;
}

}  // namespace sn::data

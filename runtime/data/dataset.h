// Training data as every backend reads it: covered-pixel samples split into training and
// validation rows. Inputs and targets are row-major floats; targets are already in the colour
// space the networks learn in (`color`).
#pragma once
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

}  // namespace sn::data

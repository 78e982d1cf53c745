// New datasets from existing ones: concatenated, a subset of the rows, split anew. Each returns
// a new dataset and leaves its arguments as they are; every row is copied whole (inputs and
// targets together), in C++, so a 64k-row dataset takes milliseconds.
//
// Keys: a result's key is a hash of its sources' keys and the operation's parameters, so the
// same operation on the same data has the same key. A source without a key (rows a script
// gave, see sn.dataset{...}) has unknown content, and so does anything made from it: the
// result's key is empty too.
#pragma once
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "data/dataset.h"

namespace sn::data {

// Training rows of each part in order, then the validation rows likewise. The parts must agree
// on input width, output width, colour space and input names (when both have names); throws
// "dataset 2 has 4 outputs, dataset 1 has 3" and the like (positions 1-based).
std::shared_ptr<Dataset> concat(const std::vector<const Dataset*>& parts);

// Keeps rows whose input `input`, component `component` (0-based), lies in [min, max].
struct RowFilter {
  std::string input;
  int component = 0;
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
};

struct SubsetRequest {
  std::optional<RowFilter> where;     // applied first
  std::optional<std::size_t> count;   // rows in all, shared by the sets in proportion
  std::optional<double> fraction;     // of each set's rows, in (0, 1]
  std::optional<uint64_t> seed;       // a seeded random choice; none = the first rows
};

// Rows keep their order and their set. `count` takes round(count * train / rows) training rows
// and the rest validation rows; `fraction` takes round(fraction * rows) of each set. A set the
// source has rows in keeps at least one row (throws when `count` is too small for that, or when
// `where` leaves a set empty).
std::shared_ptr<Dataset> subset(const Dataset& d, const SubsetRequest& r);

// Pools the training then the validation rows, permutes them (SplitMix seeded with `seed`,
// Fisher-Yates as in build.cpp) and takes the first round(split * rows) as training rows.
// `split` must lie strictly in (0, 1) and leave a row in each set.
std::shared_ptr<Dataset> resplit(const Dataset& d, double split, uint64_t seed);

}  // namespace sn::data

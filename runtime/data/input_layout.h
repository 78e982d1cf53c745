// Where each named input sits in a dataset row. Input names are G-buffer attributes (3 columns
// each, 2 for "uv") or parameters the dataset varies per row (1 column); row filters and CSV
// column names need the columns.
#pragma once
#include <string>
#include <vector>

#include "data/dataset.h"

namespace sn::data {

struct InputSlot {
  std::string name;
  int offset = 0, width = 0;  // columns [offset, offset + width) of a row
};

// The slots of d's input names, in order; empty when the dataset has no names. Throws when a
// name is not a G-buffer attribute nor a varied parameter, is listed twice, or the widths do not
// add up to d.inputs; or when a varied parameter is not among the names, is an attribute, is
// listed twice or has no finite range (min <= max).
std::vector<InputSlot> input_layout(const Dataset& d);

// The letter of component c of an input: u, v for "uv"; x, y, z for the others.
char component_letter(const std::string& input, int c);

// "normal, view" (for messages).
std::string name_list(const std::vector<std::string>& names);

}  // namespace sn::data

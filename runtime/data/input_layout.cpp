#include "data/input_layout.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "io/text.h"
#include "scene/gbuffer.h"

namespace sn::data {

std::vector<InputSlot> input_layout(const Dataset& d) {
  std::vector<InputSlot> slots;
  const auto& attributes = scene::gbuffer_attribute_names();
  for (std::size_t i = 0; i < d.conditions.size(); ++i) {
    const InputRange& c = d.conditions[i];
    const std::string what = "varied parameter '" + c.name + "'";
    if (std::find(d.input_names.begin(), d.input_names.end(), c.name) == d.input_names.end())
      throw std::invalid_argument(what + " is not among the input names {" + name_list(d.input_names) + "}");
    if (std::find(attributes.begin(), attributes.end(), c.name) != attributes.end())
      throw std::invalid_argument(what + " is a G-buffer attribute, not a parameter");
    if (!(std::isfinite(c.min) && std::isfinite(c.max) && c.min <= c.max))
      throw std::invalid_argument(what + " has the range [" + io::number_text(c.min) + ", " + io::number_text(c.max) +
                                  "]; a finite range with min <= max expected");
    for (std::size_t j = 0; j < i; ++j)
      if (d.conditions[j].name == c.name) throw std::invalid_argument(what + " is listed twice");
  }
  int offset = 0;
  for (std::size_t i = 0; i < d.input_names.size(); ++i) {
    const std::string& name = d.input_names[i];
    if (std::find(d.input_names.begin(), d.input_names.begin() + long(i), name) != d.input_names.begin() + long(i))
      throw std::invalid_argument("input name '" + name + "' is listed twice");
    bool condition = false;
    for (const auto& c : d.conditions) condition = condition || c.name == name;
    if (!condition && std::find(attributes.begin(), attributes.end(), name) == attributes.end())
      throw std::invalid_argument("input name '" + name + "' is not a G-buffer attribute (valid: " + name_list(attributes) +
                                  ") nor a varied parameter of the dataset");
    const int w = condition ? 1 : scene::attribute_width(name);
    slots.push_back({name, offset, w});
    offset += w;
  }
  if (!slots.empty() && offset != d.inputs)
    throw std::invalid_argument("input names {" + name_list(d.input_names) + "} describe " + std::to_string(offset) +
                                " columns, but the rows have " + std::to_string(d.inputs) + " inputs");
  return slots;
}

char component_letter(const std::string& input, int c) {
  if (input == "uv") return "uv"[c];
  return "xyz"[c];
}

std::string name_list(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

}  // namespace sn::data

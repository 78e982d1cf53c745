#include "data/input_layout.h"

#include <stdexcept>

#include "scene/gbuffer.h"

namespace sn::data {

std::vector<InputSlot> input_layout(const Dataset& d) {
  std::vector<InputSlot> slots;
  int offset = 0;
  for (const auto& name : d.input_names) {
    bool condition = false;
    for (const auto& c : d.conditions) condition = condition || c.name == name;
    const auto& valid = scene::gbuffer_attribute_names();
    bool known = condition;
    for (const auto& v : valid) known = known || v == name;
    if (!known)
      throw std::invalid_argument("input name '" + name + "' is not a G-buffer attribute (valid: " + name_list(valid) +
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

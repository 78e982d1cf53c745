#include "nn/mlp.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "io/text.h"
#include "nn/init.h"
#include "scene/gbuffer.h"

namespace sn::nn {

const char* init_name(Init i) { return i == Init::xavier ? "xavier" : i == Init::he ? "he" : "siren"; }

Init parse_init(const std::string& name) {
  if (name == "xavier") return Init::xavier;
  if (name == "he") return Init::he;
  if (name == "siren") return Init::siren;
  throw std::invalid_argument("unknown init '" + name + "' (valid: xavier, he, siren)");
}

Mlp::Mlp(const MlpSpec& s, Init init, uint64_t seed) : spec(s) {
  spec.validate();
  params = init_params(spec, init, seed);
}

bool Mlp::restore_best() {
  if (best_params.size() != params.size()) return false;
  params = best_params;
  touch();
  return true;
}

int input_width(const std::string& name) {
  const auto& attrs = scene::gbuffer_attribute_names();
  return std::find(attrs.begin(), attrs.end(), name) != attrs.end() ? scene::attribute_width(name) : 1;
}

std::string condition_value_problem(const Condition& c, double v) {
  if (v >= c.min && v <= c.max) return "";
  const double bound = std::abs(v - c.min) < std::abs(v - c.max) ? c.min : c.max;
  return "'" + c.name + "' = " + io::number_text(v, bound) + " lies outside the range the network was trained on, [" +
         io::number_text(c.min) + ", " + io::number_text(c.max) + "]";
}

std::string input_names_problem(const Mlp& net) {
  const auto& names = net.input_names;
  int total = 0;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (std::find(names.begin(), names.begin() + long(i), names[i]) != names.begin() + long(i))
      return "input '" + names[i] + "' is listed twice";
    total += input_width(names[i]);
  }
  if (!names.empty() && total != net.spec.inputs)
    return "input names {" + io::join(names) + "} describe " + std::to_string(total) + " input columns, the network takes " +
           std::to_string(net.spec.inputs);
  const auto& attrs = scene::gbuffer_attribute_names();
  for (std::size_t i = 0; i < net.conditions.size(); ++i) {
    const Condition& c = net.conditions[i];
    if (std::find(names.begin(), names.end(), c.name) == names.end())
      return "condition '" + c.name + "' is not among the inputs";
    if (std::find(attrs.begin(), attrs.end(), c.name) != attrs.end())
      return "condition '" + c.name + "' is a G-buffer attribute";
    for (std::size_t j = 0; j < i; ++j)
      if (net.conditions[j].name == c.name) return "condition '" + c.name + "' is listed twice";
    if (!(c.min <= c.max)) return "condition '" + c.name + "' has an empty range";
    if (std::string why = condition_value_problem(c, c.value); !why.empty()) return "condition " + why;
  }
  return "";
}

}  // namespace sn::nn

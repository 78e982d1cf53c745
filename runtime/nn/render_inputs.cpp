#include "nn/render_inputs.h"

#include <stdexcept>

#include "gl/render_target.h"

namespace sn::nn {

RenderInputs render_inputs(const Mlp& net, const scene::GBuffer& g, const std::map<std::string, double>& values) {
  const std::string what = net.spec.describe();
  if (net.spec.outputs != 3)
    throw std::invalid_argument(what + ": rendering needs a network with 3 outputs (a colour), this one has " +
                                std::to_string(net.spec.outputs));
  if (net.input_names.empty())
    throw std::invalid_argument(what + ": the network does not name the G-buffer attributes it reads; train it on a "
                                "scene dataset or give it input names first");
  RenderInputs r;
  for (const auto& c : net.conditions) {
    auto it = values.find(c.name);
    r.conditions.push_back(float(it == values.end() ? c.value : it->second));
  }
  for (const auto& [name, v] : values)
    if (!net.condition(name)) throw std::invalid_argument(what + ": no condition input '" + name + "'");
  for (const auto& a : net.input_names) {
    if (const Condition* c = net.condition(a)) {
      r.slots.push_back({-1, 0, r.conditions[std::size_t(c - net.conditions.data())]});
      continue;
    }
    (void)g.attachment(a);  // throws listing what the G-buffer holds
    const int w = scene::attribute_width(a);
    for (int k = 0; k < w; ++k) r.slots.push_back({int(r.attributes.size()), k, 0.f});
    r.attributes.push_back(a);
  }
  if (int(r.slots.size()) != net.spec.inputs)
    throw std::invalid_argument(what + ": its input attributes give " + std::to_string(r.slots.size()) +
                                " numbers, it takes " + std::to_string(net.spec.inputs));
  if (r.attributes.empty())
    throw std::invalid_argument(what + ": reads no G-buffer attribute (only conditions), so it covers no pixel");
  if (int(net.input_names.size()) > gl::RenderTarget::kMaxAttachments)
    throw std::invalid_argument(what + ": reads more attributes than a G-buffer holds");
  return r;
}

}  // namespace sn::nn

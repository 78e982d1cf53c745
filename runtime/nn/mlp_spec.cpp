#include "nn/mlp_spec.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace sn::nn {

namespace {
// "%g" of a parameter, as describe() writes it.
std::string short_number(double v) {
  char buf[32];
  snprintf(buf, sizeof buf, "%g", v);
  return buf;
}
}  // namespace

double MlpSpec::param(Activation a) const {
  switch (activation_def(a).param) {
    case ActivationParam::slope: return slope;
    case ActivationParam::omega: return omega;
    case ActivationParam::alpha: return alpha;
    default: return 0.0;
  }
}

int MlpSpec::width(int i) const {
  if (i == 0) return encodings.empty() ? inputs : encoded_width(encodings, inputs);
  if (i == layers()) return outputs;
  return hidden.at(size_t(i - 1));
}

std::size_t MlpSpec::weight_offset(int layer) const {
  std::size_t off = 0;
  for (int l = 0; l < layer; ++l) off += std::size_t(width(l) + 1) * width(l + 1);
  return off;
}

std::size_t MlpSpec::bias_offset(int layer) const {
  return weight_offset(layer) + std::size_t(width(layer)) * width(layer + 1);
}

std::size_t MlpSpec::param_count() const { return weight_offset(layers()); }

std::string MlpSpec::param_name(std::size_t j) const {
  for (int l = 0; l < layers(); ++l) {
    const std::size_t w = weight_offset(l), b = bias_offset(l), in = std::size_t(width(l));
    const std::string layer = "layer " + std::to_string(l + 1);
    if (j < b) return layer + " weight[" + std::to_string((j - w) / in + 1) + "][" + std::to_string((j - w) % in + 1) + "]";
    if (j < weight_offset(l + 1)) return layer + " bias[" + std::to_string(j - b + 1) + "]";
  }
  return "parameter " + std::to_string(j + 1) + " (beyond the network's " + std::to_string(param_count()) + ")";
}

int MlpSpec::max_width() const {
  int m = std::max(width(0), outputs);
  for (int w : hidden) m = std::max(m, w);
  return m;
}

void MlpSpec::validate() const {
  auto range = [](const std::string& what, int v, int lo, int hi) {
    if (v < lo || v > hi)
      throw std::invalid_argument(what + " must be " + std::to_string(lo) + ".." + std::to_string(hi) + ", got " +
                                  std::to_string(v));
  };
  range("inputs", inputs, 1, kMaxWidth);
  int end = 0;
  for (const InputEncoding& e : encodings) {
    if (e.offset < end || e.width < 1 || e.width > inputs || e.offset > inputs - e.width)
      throw std::invalid_argument("encoding of input '" + e.input + "': columns " + std::to_string(e.offset + 1) + ".." +
                                  std::to_string(e.offset + e.width) + " overlap another encoded input or lie past the " +
                                  std::to_string(inputs) + " inputs");
    check(e);
    end = e.offset + e.width;
  }
  if (!encodings.empty() && width(0) > kMaxEncodedWidth)
    throw std::invalid_argument("the encoded inputs are " + std::to_string(width(0)) + " wide, at most " +
                                std::to_string(kMaxEncodedWidth) + " (fewer bands, bins or a lower degree)");
  range("outputs", outputs, 1, kMaxWidth);
  range("number of hidden layers", int(hidden.size()), 1, kMaxHidden);
  for (size_t i = 0; i < hidden.size(); ++i)
    range("hidden layer " + std::to_string(i + 1) + " width", hidden[i], 1, kMaxWidth);
  if (!activation_def(activation).hidden)
    parse_activation(activation_name(activation), Position::hidden);  // throws listing the valid ones
  if (!activation_def(output_activation).output)
    parse_activation(activation_name(output_activation), Position::output, "output_activation");
  for (Activation a : {activation, output_activation}) {
    const ActivationParam p = activation_def(a).param;
    if (p == ActivationParam::slope && !(slope > 0 && slope < 1))
      throw std::invalid_argument("leaky_relu slope a must be in (0, 1), got " + short_number(slope));
    if (p == ActivationParam::omega && !(omega > 0 && omega <= 1e4))
      throw std::invalid_argument("sine omega must be in (0, 10000], got " + short_number(omega));
    if (p == ActivationParam::alpha && !(alpha > 0 && alpha <= 1e3))
      throw std::invalid_argument("elu alpha must be in (0, 1000], got " + short_number(alpha));
  }
}

std::string MlpSpec::describe() const {
  std::string s = "mlp(" + std::to_string(inputs);
  for (size_t i = 0; i < hidden.size();) {
    size_t j = i;
    while (j < hidden.size() && hidden[j] == hidden[i]) ++j;
    s += " -> " + std::to_string(hidden[i]);
    if (j - i > 1) s.append("x").append(std::to_string(j - i));
    i = j;
  }
  s += " -> " + std::to_string(outputs) + ", " + activation_name(activation);
  if (activation_def(activation).param != ActivationParam::none) s += " " + short_number(param(activation));
  if (output_activation != Activation::linear) {
    s += std::string(", out ") + activation_name(output_activation);
    if (activation_def(output_activation).param != ActivationParam::none && output_activation != activation)
      s += " " + short_number(param(output_activation));
  }
  if (color != shading::ColorSpace::rgb) s += std::string(", ") + shading::color_space_name(color);
  if (!encodings.empty()) {
    for (std::size_t i = 0; i < encodings.size(); ++i) s += (i ? ", " : "; ") + encodings[i].describe();
    s += " -> " + std::to_string(width(0)) + " inputs";
  }
  return s + ")";
}

bool MlpSpec::same_shape(const MlpSpec& o) const {
  return inputs == o.inputs && encodings == o.encodings && hidden == o.hidden && outputs == o.outputs && activation == o.activation &&
         output_activation == o.output_activation && param(activation) == o.param(activation) &&
         param(output_activation) == o.param(output_activation);
}

}  // namespace sn::nn

#include "nn/mlp_spec.h"

#include <algorithm>
#include <stdexcept>

namespace sn::nn {

namespace {
const char* kActivations[] = {"linear", "tanh", "sigmoid", "relu", "leaky_relu"};
}  // namespace

const char* activation_name(Activation a) { return kActivations[int(a)]; }

Activation parse_activation(const std::string& name) {
  for (int i = 0; i < 5; ++i)
    if (name == kActivations[i]) return Activation(i);
  throw std::invalid_argument("unknown activation '" + name + "' (valid: linear, tanh, sigmoid, relu, leaky_relu)");
}

int MlpSpec::width(int i) const {
  if (i == 0) return inputs;
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

int MlpSpec::max_width() const {
  int m = std::max(inputs, outputs);
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
  range("outputs", outputs, 1, kMaxWidth);
  range("number of hidden layers", int(hidden.size()), 1, kMaxHidden);
  for (size_t i = 0; i < hidden.size(); ++i)
    range("hidden layer " + std::to_string(i + 1) + " width", hidden[i], 1, kMaxWidth);
  if (activation == Activation::linear) throw std::invalid_argument("hidden activation cannot be linear");
  if (activation == Activation::leaky_relu && !(slope > 0 && slope < 1))
    throw std::invalid_argument("leaky_relu slope a must be in (0, 1), got " + std::to_string(slope));
}

std::string MlpSpec::describe() const {
  std::string s = "mlp(" + std::to_string(inputs);
  for (size_t i = 0; i < hidden.size();) {
    size_t j = i;
    while (j < hidden.size() && hidden[j] == hidden[i]) ++j;
    s += " -> " + std::to_string(hidden[i]);
    if (j - i > 1) s += "x" + std::to_string(j - i);
    i = j;
  }
  s += " -> " + std::to_string(outputs) + ", " + activation_name(activation);
  if (activation == Activation::leaky_relu) {
    char buf[32];
    snprintf(buf, sizeof buf, " %g", slope);
    s += buf;
  }
  if (output_activation != Activation::linear) s += std::string(", out ") + activation_name(output_activation);
  if (color != shading::ColorSpace::rgb) s += std::string(", ") + shading::color_space_name(color);
  return s + ")";
}

bool MlpSpec::same_shape(const MlpSpec& o) const {
  return inputs == o.inputs && hidden == o.hidden && outputs == o.outputs && activation == o.activation &&
         slope == o.slope && output_activation == o.output_activation;
}

}  // namespace sn::nn

// What a fully connected network is: its widths, input encodings, activations and colour
// space, and where each parameter lives in the one flat float array that every backend (cpu,
// gl, oracle, fragment shader) shares. Layer l maps width(l) -> width(l+1); its weights are
// row-major [out][in] followed by its biases [out]; layers follow each other in order.
// `inputs` is the raw input row's width (what datasets and net:forward give); width(0), what
// the first layer reads, is the encoded width (nn/encoding.h), the same when nothing is encoded.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "nn/activation.h"
#include "nn/encoding.h"
#include "shading/color.h"

namespace sn::nn {

constexpr int kMaxWidth = 64;
constexpr int kMaxHidden = 32;
constexpr int kMaxEncodedWidth = 256;  // the first layer's input width after encoding

struct MlpSpec {
  int inputs = 6;  // raw input columns, 1..kMaxWidth
  // Encoded input groups, in column order and disjoint; the other columns pass as they are.
  std::vector<InputEncoding> encodings;
  std::vector<int> hidden;  // widths of the hidden layers, 1..kMaxWidth each, 1..kMaxHidden of them
  int outputs = 3;
  Activation activation = Activation::tanh;
  Activation output_activation = Activation::linear;
  // The activations' parameters (nn/activation.h), shared by the hidden and output layers.
  double slope = 0.01;  // leaky_relu's a
  double omega = 1.0;   // sine's frequency w0: sin(w0 z)
  double alpha = 1.0;   // elu's alpha
  shading::ColorSpace color = shading::ColorSpace::rgb;

  int layers() const { return int(hidden.size()) + 1; }  // weight layers
  int width(int i) const;  // i = 0: the encoded inputs, 1..hidden: hidden, layers(): outputs
  std::size_t weight_offset(int layer) const;  // layer 0-based
  std::size_t bias_offset(int layer) const;
  std::size_t param_count() const;
  // Where flat parameter j lives, as scripts index it: "layer 2 weight[3][5]" (row = output
  // unit, column = input), "layer 1 bias[4]" (all 1-based).
  std::string param_name(std::size_t j) const;
  int max_width() const;
  // The value of `a`'s parameter (0 when it has none).
  double param(Activation a) const;
  // Throws with a message naming the bad field and its valid range.
  void validate() const;
  // "mlp(6 -> 13x4 -> 6x4 -> 3, tanh)": runs of equal widths are written WIDTHxCOUNT; encodings
  // follow: "mlp(5 -> 32x2 -> 3, relu; normal: sh 4, uv: frequency 8 -> 50 inputs)".
  std::string describe() const;
  // Same architecture and encodings (parameters can be trained in one group).
  bool same_shape(const MlpSpec& o) const;
};

}  // namespace sn::nn

#include "nn/mlp_per_net.h"

#include <string>

#include "nn/mlp_shader.h"

namespace sn::nn {

namespace {

std::string i(std::size_t v) { return std::to_string(v); }
const char* const kComponent[4] = {"x", "y", "z", "w"};

// The units 4q..4q+3 that exist in a block of `width` (mlp_live of shaders/include/mlp/activation.glsl).
std::string live(int q, int width) { return "mlp_live(" + i(std::size_t(q)) + ", " + i(std::size_t(width)) + ")"; }

// `value` with the padding components of a block of `width` set to 0 (a select: NaN passes).
std::string masked(const std::string& value, int q, int width) {
  if (4 * q + 4 <= width) return value;
  return "mix(vec4(0.0), " + value + ", " + live(q, width) + ")";
}

struct Layer {
  int in, out, in4, out4;
  std::size_t wq, bq, ui, uo;  // weights, biases (parameter vec4s); input and output units (unit vec4s)
  const char* act;             // the activation's define prefix (shaders/include/mlp/activation.glsl)
  bool keeps_grad;             // its derivative needs z: the forward pass keeps f'(z) in r_d
};

Layer layer(const MlpSpec& s, int l) {
  return Layer{s.width(l),
               s.width(l + 1),
               chunks4(s.width(l)),
               chunks4(s.width(l + 1)),
               padded_weight_chunk(s, l),
               padded_bias_chunk(s, l),
               unit_chunk(s, l),
               unit_chunk(s, l + 1),
               l == s.layers() - 1 ? "MLP_OUT_ACT" : "MLP_ACT",
               activation_def(l == s.layers() - 1 ? s.output_activation : s.activation).grad_from_output.empty()};
}

std::string p(std::size_t k) { return "r_p[" + i(k) + "]"; }
std::string a(std::size_t k) { return "r_a[" + i(k) + "]"; }
std::string d(std::size_t k) { return "r_d[" + i(k) + "]"; }
// Delta of unit j of the block starting at unit vec4 `first`.
std::string d_unit(std::size_t first, int j) { return d(first + std::size_t(j / 4)) + "." + kComponent[j % 4]; }

// Parameters and moments from the state texture, state's layout: params, m, v.
std::string load(std::size_t pq) {
  std::string s;
  const char* arrays[3] = {"r_p", "r_m", "r_v"};
  for (int m = 0; m < 3; ++m)
    for (std::size_t k = 0; k < pq; ++k)
      s += std::string(arrays[m]) + "[" + i(k) + "] = texelFetch(u_state, (base) + " + i(std::size_t(m) * pq + k) + "); ";
  return s;
}

// p, m, v = parameter vec4 k and its moments, k not a literal: a select per candidate.
std::string pick(std::size_t pq) {
  std::string s;
  for (std::size_t k = 0; k < pq; ++k) {
    const std::string c = "(k) == " + i(k) + " ? ", idx = "[" + i(k) + "]";
    s += "p = " + c + "r_p" + idx + " : p; m = " + c + "r_m" + idx + " : m; v = " + c + "r_v" + idx + " : v; ";
  }
  return s;
}

// `n` floats of row `row` of the texture `texture` as vec4 `q` (zeros past n).
std::string row_vec4(const char* texture, int n, int q) {
  std::string s = "vec4(";
  for (int c = 0; c < 4; ++c) {
    const int k = 4 * q + c;
    s += c ? ", " : "";
    s += k < n ? "texelFetch(" + std::string(texture) + ", (row) * " + i(std::size_t(n)) + " + " + i(std::size_t(k)) + ").r"
               : "0.0";
  }
  return s + ")";
}

std::string forward(const MlpSpec& s) {
  std::string out;
  for (int l = 0; l < s.layers(); ++l) {
    const Layer L = layer(s, l);
    for (int jq = 0; jq < L.out4; ++jq) {
      out += "{ vec4 z = " + p(L.bq + std::size_t(jq)) + ";";
      for (int c = 0; c < 4 && 4 * jq + c < L.out; ++c) {
        const std::size_t row = L.wq + std::size_t(4 * jq + c) * std::size_t(L.in4);
        out += std::string(" z.") + kComponent[c] + " += ";
        for (int q = 0; q < L.in4; ++q)
          out += (q ? " + " : "") + ("dot(" + p(row + std::size_t(q)) + ", " + a(L.ui + std::size_t(q)) + ")");
        out += ";";
      }
      out += " " + a(L.uo + std::size_t(jq)) + " = " + masked(std::string(L.act) + "_F(z)", jq, L.out) + ";";
      if (L.keeps_grad) out += " " + d(L.uo + std::size_t(jq)) + " = " + masked(std::string(L.act) + "_GRAD_Z(z)", jq, L.out) + ";";
      out += " } ";
    }
  }
  return out;
}

std::string output_deltas(const MlpSpec& s, int batch) {
  std::string out;
  const std::size_t first = unit_chunk(s, s.layers());
  for (int q = 0; q < chunks4(s.outputs); ++q) {
    const std::string y = a(first + std::size_t(q));
    out += "{ vec4 t = " + row_vec4("u_train_y", s.outputs, q) + "; vec4 e = " + y + " - t; ";
    out += "loss += dot(mlp_loss(e, t), vec4(1.0)); se += dot(e, e); ";
    out += "vec4 dq = (1.0 / " + i(std::size_t(batch * s.outputs)) + ".0) * mlp_loss_grad(e, t) * MLP_OUT_ACT_DERIV(" + y + ", " +
           d(first + std::size_t(q)) + "); ok = ok && mlp_finite(dq); " + d(first + std::size_t(q)) + " = dq; } ";
  }
  return out;
}

// delta_i = f'(z_i) * sum_j W[j][i] delta_j, rows in order, last layer first (not the first layer);
// f'(z_i) from the unit's output, or what the forward pass kept in its delta slot.
std::string backward(const MlpSpec& s) {
  std::string out;
  for (int l = s.layers() - 1; l >= 1; --l) {
    const Layer L = layer(s, l);
    for (int q = 0; q < L.in4; ++q) {
      const std::string dq = d(L.ui + std::size_t(q));
      out += dq + " = (";
      for (int j = 0; j < L.out; ++j)
        out += (j ? " + " : "") + p(L.wq + std::size_t(j * L.in4 + q)) + " * " + d_unit(L.uo, j);
      out += ") * MLP_ACT_DERIV(" + a(L.ui + std::size_t(q)) + ", " + dq + "); ok = ok && mlp_finite(" + dq + "); ";
    }
  }
  return out;
}

// Calls f(k, share, live) for every parameter vec4 k: `share` is this sample's part of its
// gradient (weights: delta_j times input units 4q..4q+3; biases: the deltas), `live` its mask.
template <class F>
void each_param(const MlpSpec& s, F&& f) {
  for (int l = 0; l < s.layers(); ++l) {
    const Layer L = layer(s, l);
    for (int j = 0; j < L.out; ++j)
      for (int q = 0; q < L.in4; ++q)
        f(L.wq + std::size_t(j * L.in4 + q), d_unit(L.uo, j) + " * " + a(L.ui + std::size_t(q)), live(q, L.in));
    for (int q = 0; q < L.out4; ++q) f(L.bq + std::size_t(q), d(L.uo + std::size_t(q)), live(q, L.out));
  }
}

}  // namespace

gl::Defines per_net_step_defines(const MlpSpec& s, int batch) {
  gl::Defines defs;
  const std::size_t pq = padded_chunks(s);
  defs["MLP_R_LOAD(base)"] = load(pq);
  defs["MLP_R_PICK(k)"] = pick(pq);
  std::string zero, accumulate, adam;
  each_param(s, [&](std::size_t k, const std::string& share, const std::string& live) {
    zero += "r_g[" + i(k) + "] = vec4(0.0); ";
    accumulate += "r_g[" + i(k) + "] += " + share + "; ";
    adam += "adam_at(" + i(k) + ", " + live + "); ";
  });
  defs["MLP_R_ZERO"] = zero;
  std::string inputs;
  if (s.encodings.empty()) {
    for (int q = 0; q < chunks4(s.inputs); ++q) inputs += a(std::size_t(q)) + " = " + row_vec4("u_train_x", s.inputs, q) + "; ";
  } else {  // the raw row, then its encoding (shaders/include/mlp/encoding.glsl)
    inputs = "{ float x_[" + i(std::size_t(s.inputs)) + "] = float[](";
    for (int k = 0; k < s.inputs; ++k)
      inputs += (k ? ", " : "") + ("texelFetch(u_train_x, (row) * " + i(std::size_t(s.inputs)) + " + " + i(std::size_t(k)) + ").r");
    inputs += "); vec4 e_[" + i(std::size_t(chunks4(s.width(0)))) + "]; mlp_encode(x_, e_); ";
    for (int q = 0; q < chunks4(s.width(0)); ++q) inputs += a(std::size_t(q)) + " = e_[" + i(std::size_t(q)) + "]; ";
    inputs += "} ";
  }
  defs["MLP_R_INPUTS(row)"] = inputs;
  defs["MLP_R_FORWARD"] = forward(s);
  defs["MLP_R_OUTPUT(row)"] = output_deltas(s, batch);
  defs["MLP_R_BACKWARD"] = backward(s);
  defs["MLP_R_ACCUMULATE"] = accumulate;
  defs["MLP_R_ADAM"] = adam;
  return defs;
}

}  // namespace sn::nn

#include "nn/mlp_shader.h"

#include <algorithm>
#include <cstdio>

#include "nn/mlp_per_net.h"

namespace sn::nn {

namespace {

std::string num(std::size_t v) { return std::to_string(v); }

// Loops over a layer's input vec4s are unrolled up to this many; longer ones stay loops: the
// unrolled code of a wide layer (every access a loop over the SIMD lanes on llvmpipe) takes
// LLVM minutes to compile.
constexpr int kUnrollInputChunks = 4;

// Consecutive layers of equal shape share one copy of the layer code, a loop over them: the
// shader's size (and LLVM's compile time, superlinear in it) no longer grows with depth. The
// first and the last layer are runs of their own (backpropagation skips the first; the last has
// the output activation).
struct Run {
  int first, count;
};
std::vector<Run> layer_runs(const MlpSpec& s) {
  std::vector<Run> runs;
  for (int l = 0; l < s.layers(); ++l) {
    bool joins = !runs.empty() && l != 1 && l != s.layers() - 1 && s.width(l) == s.width(l + 1) &&
                 s.width(runs.back().first) == s.width(l) && s.width(runs.back().first + 1) == s.width(l + 1);
    if (joins)
      ++runs.back().count;
    else
      runs.push_back({l, 1});
  }
  return runs;
}

std::string run_row(const MlpSpec& s, const Run& r) {
  const int in = s.width(r.first), out = s.width(r.first + 1);
  const std::string q = chunks4(in) <= kUnrollInputChunks ? num(chunks4(in)) : "(" + num(chunks4(in)) + " + u_zero)";
  return "X(" + num(r.first) + ", " + num(r.count) + ", " + num(in) + ", " + num(out) + ", " + num(chunks4(in)) + ", " +
         num(chunks4(out)) + ", " + num(padded_weight_chunk(s, r.first)) + ", " + num(unit_chunk(s, r.first)) + ", " + q +
         ")";
}

}  // namespace

std::size_t padded_weight_chunk(const MlpSpec& s, int layer) {
  std::size_t off = 0;
  for (int l = 0; l < layer; ++l) off += std::size_t(s.width(l + 1)) * chunks4(s.width(l)) + chunks4(s.width(l + 1));
  return off;
}

std::size_t padded_bias_chunk(const MlpSpec& s, int layer) {
  return padded_weight_chunk(s, layer) + std::size_t(s.width(layer + 1)) * chunks4(s.width(layer));
}

std::size_t padded_chunks(const MlpSpec& s) { return padded_weight_chunk(s, s.layers()); }

std::size_t unit_chunk(const MlpSpec& s, int i) {
  std::size_t off = 0;
  for (int k = 0; k < i; ++k) off += std::size_t(chunks4(s.width(k)));
  return off;
}

std::size_t unit_chunks(const MlpSpec& s) { return unit_chunk(s, s.layers() + 1); }

void pack_padded(const MlpSpec& s, const float* flat, float* padded) {
  std::fill(padded, padded + 4 * padded_chunks(s), 0.f);
  for (int l = 0; l < s.layers(); ++l) {
    const int in = s.width(l), out = s.width(l + 1), row = 4 * chunks4(in);
    const float* w = flat + s.weight_offset(l);
    float* pw = padded + 4 * padded_weight_chunk(s, l);
    for (int j = 0; j < out; ++j)
      for (int i = 0; i < in; ++i) pw[j * row + i] = w[j * in + i];
    const float* b = flat + s.bias_offset(l);
    float* pb = padded + 4 * padded_bias_chunk(s, l);
    for (int j = 0; j < out; ++j) pb[j] = b[j];
  }
}

std::vector<float> pack_padded(const MlpSpec& s, const float* flat) {
  std::vector<float> p(4 * padded_chunks(s));
  pack_padded(s, flat, p.data());
  return p;
}

void unpack_padded(const MlpSpec& s, const float* padded, float* flat) {
  for (int l = 0; l < s.layers(); ++l) {
    const int in = s.width(l), out = s.width(l + 1), row = 4 * chunks4(in);
    float* w = flat + s.weight_offset(l);
    const float* pw = padded + 4 * padded_weight_chunk(s, l);
    for (int j = 0; j < out; ++j)
      for (int i = 0; i < in; ++i) w[j * in + i] = pw[j * row + i];
    float* b = flat + s.bias_offset(l);
    const float* pb = padded + 4 * padded_bias_chunk(s, l);
    for (int j = 0; j < out; ++j) b[j] = pb[j];
  }
}

gl::Defines mlp_defines(const MlpSpec& s) {
  gl::Defines d;
  d["MLP_IN"] = num(s.width(0));
  d["MLP_RAW_IN"] = num(s.inputs);
  d["MLP_ENCODED"] = s.encodings.empty() ? "0" : "1";
  d["MLP_OUT"] = num(s.outputs);
  d["MLP_IN4"] = num(chunks4(s.width(0)));
  d["MLP_OUT4"] = num(chunks4(s.outputs));
  d["MLP_LAYERS"] = num(s.layers());
  d["MLP_PARAMS"] = num(s.param_count());
  d["MLP_PQ"] = num(padded_chunks(s));
  d["MLP_UQ"] = num(unit_chunks(s));
  d["MLP_OUT_UQ"] = num(unit_chunk(s, s.layers()));
  d["MLP_MAX_WIDTH"] = num(s.max_width());
  auto activation = [&](const std::string& prefix, Activation a) {
    const std::string fn = activation_glsl_function(a), p = gl::float_literal(s.param(a));
    d[prefix + "_F(z)"] = fn + "(z, " + p + ")";
    d[prefix + "_GRAD_Z(z)"] = fn + "_grad(z, " + p + ")";
    const bool from_output = !activation_def(a).grad_from_output.empty();
    d[prefix + "_FROM_OUTPUT"] = from_output ? "1" : "0";
    if (from_output) d[prefix + "_GRAD_A(a)"] = fn + "_grad_a(a, " + p + ")";
  };
  activation("MLP_ACT", s.activation);
  activation("MLP_OUT_ACT", s.output_activation);
  d["MLP_COLOR"] = num(int(s.color));
  const std::vector<Run> runs = layer_runs(s);
  std::string fwd, rev, inner_rev;
  for (std::size_t i = 0; i < runs.size(); ++i) fwd += (i ? " " : "") + run_row(s, runs[i]);
  for (std::size_t i = runs.size(); i-- > 0;) {
    rev += (rev.empty() ? "" : " ") + run_row(s, runs[i]);
    if (runs[i].first > 0) inner_rev += (inner_rev.empty() ? "" : " ") + run_row(s, runs[i]);
  }
  d["MLP_RUN_TABLE(X)"] = fwd;
  d["MLP_RUN_TABLE_REVERSED(X)"] = rev;
  d["MLP_INNER_RUN_TABLE_REVERSED(X)"] = inner_rev;
  return d;
}

gl::Includes mlp_includes(const MlpSpec& s) {
  gl::Includes src;
  src["mlp/act_hidden.glsl"] = activation_glsl_source(s.activation);
  src["mlp/act_output.glsl"] = s.output_activation == s.activation ? "" : activation_glsl_source(s.output_activation);
  src["mlp/enc_net.glsl"] = s.encodings.empty() ? "" : encoding_glsl_source(s.encodings, s.inputs);
  return src;
}

std::string TrainLayout::describe() const {
  if (per_net) return "one network per invocation, params+moments+gradient+units in registers";
  std::string in, out;
  auto put = [](std::string& s, const char* what) { s += (s.empty() ? "" : "+") + std::string(what); };
  (params_shared ? put(in, "params") : put(out, "params"));
  (moments_shared ? put(in, "moments") : put(out, "moments"));
  (units_shared ? put(in, "units") : put(out, "units"));
  char kib[32];
  std::snprintf(kib, sizeof kib, "%.1f KiB", double(shared_bytes) / 1024.0);
  std::string s = in.empty() ? std::string("nothing") : in;
  s += " in shared memory (" + std::string(kib) + ")";
  if (!out.empty()) s += ", " + out + " in a storage buffer";
  return s;
}

TrainLayout plan_train_layout(const MlpSpec& spec, int batch, std::size_t max_shared, bool per_net) {
  const std::size_t PQ = padded_chunks(spec), B = std::size_t(batch);
  // Per sample: the units of every block, the deltas of every block but the inputs.
  const std::size_t UQ = unit_chunks(spec);
  const std::size_t units_q = B * (UQ + (UQ - std::size_t(chunks4(spec.width(0)))));
  const std::size_t fixed = 16 + 8 * B + 64;  // flags, the loss reduction, a margin for the compiler's padding
  TrainLayout t;
  if (per_net && PQ <= kPerNetMaxChunks) {
    t.per_net = true;
    t.params_shared = t.moments_shared = t.units_shared = false;
    return t;
  }
  auto total = [&] {
    return fixed + 16 * ((t.params_shared ? PQ : 0) + (t.moments_shared ? 2 * PQ : 0) + (t.units_shared ? units_q : 0));
  };
  if (total() > max_shared) t.moments_shared = false;
  if (total() > max_shared) t.units_shared = false;
  if (total() > max_shared) t.params_shared = false;
  t.shared_bytes = total();
  t.scratch_vec4s = (t.params_shared ? 0 : PQ) + (t.moments_shared ? 0 : 2 * PQ) + (t.units_shared ? 0 : units_q);
  return t;
}

namespace {
void loss_defines(gl::Defines& d, const Loss& loss) {
  d["MLP_LOSS"] = num(std::size_t(loss.kind));
  d["MLP_LOSS_DELTA"] = gl::float_literal(loss.delta);
}
}  // namespace

gl::Defines train_defines(const MlpSpec& spec, int batch, const TrainLayout& t, const Loss& loss) {
  gl::Defines d = mlp_defines(spec);
  loss_defines(d, loss);
  d["MLP_BATCH"] = num(std::size_t(batch));
  d["MLP_PARAMS_SHARED"] = t.params_shared ? "1" : "0";
  d["MLP_MOMENTS_SHARED"] = t.moments_shared ? "1" : "0";
  d["MLP_UNITS_SHARED"] = t.units_shared ? "1" : "0";
  d["MLP_SCRATCH"] = num(t.scratch_vec4s);
  if (t.per_net) {
    d["MLP_NETS_PER_GROUP"] = num(std::size_t(kNetsPerGroup));
    for (auto& [name, code] : per_net_step_defines(spec, batch)) d[name] = code;
  }
  return d;
}

int eval_local_size(const MlpSpec& spec, std::size_t max_shared) {
  int n = 8;
  while (n > 1 && std::size_t(n) * (16 * unit_chunks(spec) + 8) + 64 > max_shared) n /= 2;
  return n;
}

gl::Defines eval_defines(const MlpSpec& spec, bool loss_mode, int local_size, const Loss& loss) {
  gl::Defines d = mlp_defines(spec);
  loss_defines(d, loss);
  d["MLP_EVAL_LOSS"] = loss_mode ? "1" : "0";
  d["MLP_EVAL_LOCAL_SIZE"] = num(std::size_t(local_size));
  return d;
}

}  // namespace sn::nn

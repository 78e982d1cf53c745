#include "nn/mlp_shader.h"

#include <cstdio>

namespace sn::nn {

namespace {

std::string num(std::size_t v) { return std::to_string(v); }

// A float literal GLSL reads back as the same float.
std::string float_literal(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.9g", float(v));
  std::string s = buf;
  if (s.find_first_of(".eE") == std::string::npos) s += ".0";
  return s;
}

std::string layer_row(const MlpSpec& s, int l) {
  return "X(" + num(l) + ", " + num(s.width(l)) + ", " + num(s.width(l + 1)) + ", " + num(s.weight_offset(l)) + ", " +
         num(s.bias_offset(l)) + ", " + num(unit_offset(s, l)) + ", " + num(unit_offset(s, l + 1)) + ")";
}

}  // namespace

std::size_t unit_offset(const MlpSpec& spec, int i) {
  std::size_t off = 0;
  for (int k = 0; k < i; ++k) off += std::size_t(spec.width(k));
  return off;
}

std::size_t unit_count(const MlpSpec& spec) { return unit_offset(spec, spec.layers() + 1); }

gl::Defines mlp_defines(const MlpSpec& s) {
  gl::Defines d;
  d["MLP_IN"] = num(s.inputs);
  d["MLP_OUT"] = num(s.outputs);
  d["MLP_LAYERS"] = num(s.layers());
  d["MLP_PARAMS"] = num(s.param_count());
  d["MLP_UNITS"] = num(unit_count(s));
  d["MLP_MAX_WIDTH"] = num(s.max_width());
  d["MLP_ACT"] = num(int(s.activation));
  d["MLP_OUT_ACT"] = num(int(s.output_activation));
  d["MLP_SLOPE"] = float_literal(s.slope);
  d["MLP_COLOR"] = num(int(s.color));
  std::string fwd, rev, hidden_rev;
  for (int l = 0; l < s.layers(); ++l) fwd += (l ? " " : "") + layer_row(s, l);
  for (int l = s.layers() - 1; l >= 0; --l) rev += (rev.empty() ? "" : " ") + layer_row(s, l);
  for (int l = s.layers() - 1; l >= 1; --l) hidden_rev += (hidden_rev.empty() ? "" : " ") + layer_row(s, l);
  d["MLP_LAYER_TABLE(X)"] = fwd;
  d["MLP_LAYER_TABLE_REVERSED(X)"] = rev;
  // Layers whose inputs are hidden units (all but the first): the ones backpropagation passes through.
  d["MLP_INNER_LAYER_TABLE_REVERSED(X)"] = hidden_rev;
  return d;
}

std::string TrainLayout::describe() const {
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

TrainLayout plan_train_layout(const MlpSpec& spec, int batch, std::size_t max_shared) {
  const std::size_t P = spec.param_count(), U = unit_count(spec), B = std::size_t(batch);
  const std::size_t params = 4 * P, moments = 8 * P;
  const std::size_t units = 4 * B * ((U - std::size_t(spec.outputs)) + (U - std::size_t(spec.inputs)));
  const std::size_t fixed = 16 + 8 * B + 64;  // flags, the loss reduction, a margin for the compiler's padding
  TrainLayout t;
  auto total = [&] {
    return fixed + (t.params_shared ? params : 0) + (t.moments_shared ? moments : 0) + (t.units_shared ? units : 0);
  };
  if (total() > max_shared) t.moments_shared = false;
  if (total() > max_shared) t.units_shared = false;
  if (total() > max_shared) t.params_shared = false;
  t.shared_bytes = total();
  t.scratch_floats = (t.params_shared ? 0 : P) + (t.moments_shared ? 0 : 2 * P) + (t.units_shared ? 0 : units / 4);
  return t;
}

gl::Defines train_defines(const MlpSpec& spec, int batch, const TrainLayout& t) {
  gl::Defines d = mlp_defines(spec);
  d["MLP_BATCH"] = num(std::size_t(batch));
  d["MLP_PARAMS_SHARED"] = t.params_shared ? "1" : "0";
  d["MLP_MOMENTS_SHARED"] = t.moments_shared ? "1" : "0";
  d["MLP_UNITS_SHARED"] = t.units_shared ? "1" : "0";
  d["MLP_SCRATCH"] = num(t.scratch_floats);
  return d;
}

gl::Defines eval_defines(const MlpSpec& spec, bool loss_mode, std::size_t max_shared) {
  gl::Defines d = mlp_defines(spec);
  const std::size_t need = 4 * spec.param_count() + 8 * kEvalLocalSize + 64;
  d["MLP_EVAL_SHARED_WEIGHTS"] = need <= max_shared ? "1" : "0";
  d["MLP_EVAL_LOSS"] = loss_mode ? "1" : "0";
  d["MLP_EVAL_LOCAL_SIZE"] = num(kEvalLocalSize);
  return d;
}

}  // namespace sn::nn

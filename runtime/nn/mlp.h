// A network as the runtime holds it: its spec, its parameters in the shared flat layout
// (nn/mlp_spec.h), what it reads, and counters the renderer and scripts watch. Adam moments
// are not here: they belong to one training run (nn/trainer.h).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "nn/mlp_spec.h"

namespace sn::nn {

enum class Init { xavier, he, siren };
const char* init_name(Init i);
Init parse_init(const std::string& name);  // "xavier" | "he" | "siren"; throws listing the valid names

// An input that is a lighting-model parameter (a network conditioned on it, trained on a dataset
// that varied it per row): its training range, and the value it takes when the network renders
// (a uniform; the middle of the range until set).
struct Condition {
  std::string name;
  double min = 0, max = 0, value = 0;
};

struct Mlp {
  MlpSpec spec;
  std::vector<float> params;  // spec.param_count() floats, layout of MlpSpec
  // G-buffer attributes the input vector is assembled from, in order (e.g. {"normal", "view"});
  // empty until set by the user or by the first training on a data::Dataset that names them.
  std::vector<std::string> input_names;
  // The input names that are conditions rather than G-buffer attributes (one number each).
  std::vector<Condition> conditions;
  const Condition* condition(const std::string& name) const {
    for (const auto& c : conditions)
      if (c.name == name) return &c;
    return nullptr;
  }
  // Bumped on every change of `params` (edits, training, restore_best, load): the renderer
  // re-uploads the weights when it differs from what it last uploaded.
  uint64_t version = 1;
  uint64_t trained_steps = 0;  // Adam steps applied over the network's whole life
  // Parameters at the epoch of the lowest validation MSE of the last training run (empty before
  // any run); `restore_best()` copies them into `params`.
  std::vector<float> best_params;
  double best_val_mse = 0;
  int best_epoch = 0;  // 1-based epoch of best_params, 0 = none

  Mlp() = default;
  // Validates the spec and initialises the parameters (see nn/init.h).
  Mlp(const MlpSpec& s, Init init, uint64_t seed);

  void touch() { ++version; }
  bool restore_best();  // false when there is no best snapshot

  // Views on layer `l` (0-based): weights row-major [out][in], then biases [out].
  float* weights(int l) { return params.data() + spec.weight_offset(l); }
  float* biases(int l) { return params.data() + spec.bias_offset(l); }
  const float* weights(int l) const { return params.data() + spec.weight_offset(l); }
  const float* biases(int l) const { return params.data() + spec.bias_offset(l); }
};

// The width of an input by name: a G-buffer attribute's (3, or 2 for "uv"), else 1 (a
// lighting-model parameter a dataset varies per row: a condition).
int input_width(const std::string& name);
// Why condition c cannot take the value v (empty when it can): it must lie in the range the
// network was trained on.
std::string condition_value_problem(const Condition& c, double v);
// Why the network's input names and conditions cannot be what it reads (empty when they can):
// the names' widths must add up to its inputs, no name twice; a condition names an input that
// is not a G-buffer attribute, once, and its value lies in its range.
std::string input_names_problem(const Mlp& net);

}  // namespace sn::nn

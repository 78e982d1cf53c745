#include "nn/mlp.h"

#include <stdexcept>

#include "nn/init.h"

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

}  // namespace sn::nn

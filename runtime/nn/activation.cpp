#include "nn/activation.h"

#include <deque>
#include <stdexcept>

#include "io/text.h"
#include "nn/registry_name.h"

namespace sn::nn {

std::vector<ActivationDef> builtin_activations();  // nn/activation_builtin.cpp, in Builtin order

namespace {

// A deque: handles and references stay valid as definitions are added.
using Defs = std::deque<ActivationDef>;

int lookup(const Defs& defs, const std::string& name) {
  for (std::size_t i = 0; i < defs.size(); ++i) {
    if (defs[i].replaced) continue;
    if (defs[i].name == name) return int(i);
    for (const auto& a : defs[i].aliases)
      if (a == name) return int(i);
  }
  return -1;
}

// Whether two definitions compute the same network function (their twins may differ: they are
// the oracle's, never run by a network).
bool same_function(const ActivationDef& a, const ActivationDef& b) {
  return a.glsl == b.glsl && a.grad == b.grad && a.grad_from_output == b.grad_from_output && a.param == b.param &&
         a.hidden == b.hidden && a.output == b.output;
}

// The one way into the registry, for built-ins and user definitions alike.
int add(Defs& defs, ActivationDef def, bool builtin) {
  check_activation_def(def);
  const int at = lookup(defs, def.name);
  if (at >= 0) {
    if (at < int(Builtin::count))
      throw std::invalid_argument("activation '" + def.name + "' is built in; choose another name");
    if (!builtin) {  // a script run again (live mode) defines it anew
      def.aliases.clear();
      if (same_function(defs[std::size_t(at)], def)) {
        defs[std::size_t(at)] = std::move(def);
        return at;
      }
      defs[std::size_t(at)].replaced = true;  // kept for the networks built with it
    }
  }
  for (const auto& a : def.aliases)
    if (lookup(defs, a) >= 0) throw std::invalid_argument("activation alias '" + a + "' is taken");
  defs.push_back(std::move(def));
  return int(defs.size()) - 1;
}

}  // namespace

void check_activation_def(const ActivationDef& def) {
  for (const auto& a : def.aliases)
    if (!valid_registry_name(a)) throw std::invalid_argument("activation alias '" + a + "': use lower-case letters, digits and _");
  if (!valid_registry_name(def.name))
    throw std::invalid_argument("activation name '" + def.name + "': use lower-case letters, digits and _ (at most 40)");
  if (def.glsl.empty() || def.grad.empty())
    throw std::invalid_argument("activation '" + def.name + "' needs both its GLSL and the GLSL of its derivative");
  if (!def.f || !def.df) throw std::invalid_argument("activation '" + def.name + "' needs its function and derivative twins");
}

namespace {

Defs& registry() {
  static Defs defs = [] {
    Defs d;
    for (auto& def : builtin_activations()) add(d, std::move(def), true);
    return d;
  }();
  return defs;
}

}  // namespace

const char* activation_param_name(ActivationParam p) {
  switch (p) {
    case ActivationParam::slope: return "slope";
    case ActivationParam::omega: return "omega";
    case ActivationParam::alpha: return "alpha";
    default: return "";
  }
}

Activation register_activation(ActivationDef def) {
  def.simd = -1;  // only built-ins have SIMD code
  return Activation(add(registry(), std::move(def), false));
}

const ActivationDef& activation_def(Activation a) {
  const Defs& defs = registry();
  if (a.id < 0 || std::size_t(a.id) >= defs.size()) throw std::out_of_range("no activation with id " + std::to_string(a.id));
  return defs[std::size_t(a.id)];
}

const char* activation_name(Activation a) { return activation_def(a).name.c_str(); }

bool activation_has_cpu_code(Activation a) {
  const ActivationDef& d = activation_def(a);
  return d.simd >= 0 || d.cpu_f;
}

std::string activation_without_cpu_code(Activation a) {
  const ActivationDef& d = activation_def(a);
  return "activation '" + d.name + "' is a definition without cpu code" + (d.cpu_missing.empty() ? "" : " (" + d.cpu_missing + ")");
}

bool find_activation(const std::string& name, Activation* out) {
  const int at = lookup(registry(), name);
  if (at < 0) return false;
  *out = Activation(at);
  return true;
}

std::vector<std::string> activation_names(Position position) {
  std::vector<std::string> names;
  for (const auto& d : registry()) {
    if (d.replaced || !(position == Position::hidden ? d.hidden : d.output)) continue;
    names.push_back(d.name);
    for (const auto& a : d.aliases) names.push_back(a);
  }
  return names;
}

Activation parse_activation(const std::string& name, Position position, const std::string& option) {
  Activation a;
  const bool known = find_activation(name, &a);
  const ActivationDef* d = known ? &activation_def(a) : nullptr;
  if (d && (position == Position::hidden ? d->hidden : d->output)) return a;
  const char* where = position == Position::hidden ? "hidden layers" : "the output layer";
  const std::string valid = " (valid: " + io::join(activation_names(position)) + ")";
  if (d) throw std::invalid_argument(option + " '" + name + "' cannot be used for " + where + valid);
  throw std::invalid_argument("unknown " + option + " '" + name + "'" + valid);
}

std::string activation_glsl_function(Activation a) { return "sn_act_" + activation_def(a).name; }

namespace {
// A body as given, or one expression made into a return.
std::string body(const std::string& code) {
  if (code.find("return") != std::string::npos) return code;
  return "return " + code + "\n;";  // a line of its own: the code may end in a // comment
}
}  // namespace

std::string activation_glsl_function(const ActivationDef& d, ActivationPart part) {
  const std::string fn = "sn_act_" + d.name;
  // The body starts on the header's line: an error's line number counts within the given text.
  // `x` is the pre-activation too (users' definitions read more naturally as f(x)).
  switch (part) {
    case ActivationPart::f: return "vec4 " + fn + "(vec4 z, float p) { vec4 x = z; " + body(d.glsl) + "\n}\n";
    case ActivationPart::grad: return "vec4 " + fn + "_grad(vec4 z, float p) { vec4 x = z; " + body(d.grad) + "\n}\n";
    default:
      return d.grad_from_output.empty()
                 ? ""
                 : "vec4 " + fn + "_grad_a(vec4 a, float p) { " + body(d.grad_from_output) + "\n}\n";
  }
}

std::string activation_glsl_source(Activation a) {
  const ActivationDef& d = activation_def(a);
  return activation_glsl_function(d, ActivationPart::f) + activation_glsl_function(d, ActivationPart::grad) +
         activation_glsl_function(d, ActivationPart::grad_from_output);
}

}  // namespace sn::nn

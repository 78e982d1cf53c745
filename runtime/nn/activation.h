// Activations as plug-ins: one registry maps a name to everything a backend needs, the GLSL
// of the function and of its derivative (both of the pre-activation z), a double-precision twin
// for the oracle, and for built-ins the id of their SIMD code in the cpu backend. The built-ins
// register themselves (nn/activation_builtin.cpp) through register_activation(), the same call a
// user's definition goes through.
//
// An activation may take one scalar parameter (leaky_relu's slope, sine's omega, elu's alpha);
// MlpSpec holds its value under the parameter's name.
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace sn::nn {

struct ActivationExpr;

// A registered activation, by its index in the registry. The built-ins have fixed ids.
struct Activation {
  int id = 1;
  Activation() = default;
  explicit Activation(int i) : id(i) {}
  bool operator==(Activation o) const { return id == o.id; }
  bool operator!=(Activation o) const { return id != o.id; }
  static const Activation linear, tanh, sigmoid, relu, leaky_relu, sine, softplus, squareplus, elu, gelu, swish,
      exponential;
};

// The built-ins' ids (Activation::id) and the cpu backend's kernel templates' argument.
enum class Builtin : int {
  linear, tanh, sigmoid, relu, leaky_relu, sine, softplus, squareplus, elu, gelu, swish, exponential, count
};

inline const Activation Activation::linear{int(Builtin::linear)};
inline const Activation Activation::tanh{int(Builtin::tanh)};
inline const Activation Activation::sigmoid{int(Builtin::sigmoid)};
inline const Activation Activation::relu{int(Builtin::relu)};
inline const Activation Activation::leaky_relu{int(Builtin::leaky_relu)};
inline const Activation Activation::sine{int(Builtin::sine)};
inline const Activation Activation::softplus{int(Builtin::softplus)};
inline const Activation Activation::squareplus{int(Builtin::squareplus)};
inline const Activation Activation::elu{int(Builtin::elu)};
inline const Activation Activation::gelu{int(Builtin::gelu)};
inline const Activation Activation::swish{int(Builtin::swish)};
inline const Activation Activation::exponential{int(Builtin::exponential)};

// Which scalar of MlpSpec an activation reads.
enum class ActivationParam { none, slope, omega, alpha };
const char* activation_param_name(ActivationParam p);  // "slope", "omega", "alpha"

struct ActivationDef {
  std::string name;
  std::vector<std::string> aliases;  // other names that parse to it ("silu" for swish)
  bool hidden = true, output = true;  // where it may be used
  ActivationParam param = ActivationParam::none;
  // GLSL bodies over `vec4 z` and `float p` (the parameter): statements ending in a return, or
  // one expression. `grad` is d f / d z. `grad_from_output`, optional, is the same derivative
  // over `vec4 a` = f(z) (the backward pass then needs no stored derivative).
  std::string glsl, grad, grad_from_output;
  std::string origin;  // where errors in the GLSL point: "built-in", or "script.lua:12"
  std::function<double(double z, double p)> f, df;  // double twins
  int simd = -1;  // Builtin id of its SIMD code in the cpu backend; -1: none
  // A user's definition on the cpu backend, translated by define_activation (nn/activation_expr.h):
  // glsl alone (inference), and glsl with grad (training); null where they do not translate, and
  // cpu_missing says why.
  std::shared_ptr<const ActivationExpr> cpu_f, cpu_both;
  std::string cpu_missing;
  // A later definition of the name replaced this one: the name finds that one now, and networks
  // built before keep this one (they hold the handle).
  bool replaced = false;
};

// Throws for a name or alias outside the registry's rules, or a definition missing a part
// (its GLSL, its derivative's, a twin): what register_activation checks first.
void check_activation_def(const ActivationDef& def);

// Registers a definition (its name and aliases must be new, or name an earlier user definition,
// which it replaces); returns its handle. Throws for a bad name or a clash with a built-in.
// A network holds its activation by handle: one that replaces an earlier definition with other
// GLSL gets a handle of its own, so networks built before keep computing what they were built
// (and trained) with; the same GLSL again (a script run again) keeps the earlier handle.
Activation register_activation(ActivationDef def);
const ActivationDef& activation_def(Activation a);
const char* activation_name(Activation a);
// Whether the cpu backend runs `a` (its SIMD code, or its translated GLSL); if not, why:
// "activation 'NAME' is a definition without cpu code (REASON)".
bool activation_has_cpu_code(Activation a);
std::string activation_without_cpu_code(Activation a);

enum class Position { hidden, output };
// The activation called `name` valid in `position`; throws listing exactly the names valid there
// (`option` names the option in the message, e.g. "activation" or "output_activation").
Activation parse_activation(const std::string& name, Position position = Position::hidden,
                            const std::string& option = "activation");
// Every name valid in `position`, in registry order (aliases after their activation).
std::vector<std::string> activation_names(Position position);
// The registered activation called `name` (or an alias), if any.
bool find_activation(const std::string& name, Activation* out);

// GLSL function names of an activation: <fn>(vec4 z, float p), <fn>_grad, <fn>_grad_a.
std::string activation_glsl_function(Activation a);
// The GLSL file (as an in-memory #include) defining an activation's functions, and one of them.
std::string activation_glsl_source(Activation a);
enum class ActivationPart { f, grad, grad_from_output };
std::string activation_glsl_function(const ActivationDef& def, ActivationPart part);

}  // namespace sn::nn

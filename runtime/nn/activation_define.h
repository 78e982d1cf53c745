// A user's activation (sn.activation.define): checked before it is registered, so that a broken
// definition is an error at the line that defines it, never a wrong network later:
//  - the twins (f, df: the Lua functions) are finite on [-4, 4] and df agrees with central
//    differences of f;
//  - the GLSL of f and of f' compiles (errors name `def.origin` and the line within that text) and
//    agrees with the twins at the same points.
// Then the GLSL is translated for the cpu backend (nn/activation_expr.h) and held to the twins
// at the same points; where it does not translate or agree, the definition runs on gl only, and
// the cpu backend refuses it, saying why and naming backend = "gl".
#pragma once
#include "nn/activation.h"

namespace sn::nn {

Activation define_activation(ActivationDef def);

}  // namespace sn::nn

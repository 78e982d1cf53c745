// A user's input encoding (sn.encoding.define): checked before anything uses it, so that a
// broken definition is an error at the line that defines it, never a wrong network later:
//  - the twin (a Lua function of the input's components) gives exactly the declared number of
//    finite outputs for every input width and count the encoding accepts;
//  - the GLSL compiles (errors name `def.origin` and the line within that text) and agrees with
//    the twin within 1e-4 on sample inputs.
// A definition that fails leaves the registry as it was (an earlier definition of the name
// included).
#pragma once
#include "nn/encoding.h"

namespace sn::nn {

Encoding define_encoding(EncodingDef def);

}  // namespace sn::nn

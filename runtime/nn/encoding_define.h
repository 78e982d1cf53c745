// A user's input encoding (sn.encoding.define): checked before anything uses it, so that a
// broken definition is an error at the line that defines it, never a wrong network later:
//  - the twin (a Lua function of the input's components) gives exactly the declared number of
//    finite outputs for every input width and count the encoding accepts;
//  - the GLSL compiles (errors name `def.origin` and the line within that text) and agrees with
//    the twin (twin_agrees) on sample inputs: components in [-0.9, 0.9], and out to +-300, as
//    positions and varied parameters reach.
// A definition that fails leaves the registry as it was (an earlier definition of the name
// included).
#pragma once
#include <cstddef>
#include <vector>

#include "nn/encoding.h"

namespace sn::nn {

Encoding define_encoding(EncodingDef def);

// The checks above, of a registered encoding (tests hold the built-ins to them too).
void check_definition(Encoding kind);

// Whether the GLSL's value `glsl` and the twin's `twin` of one output agree for the input x[0..width):
// within 1e-4 (1 + |twin|) max(1, |x_c|), the float rounding of the input growing with its
// magnitude; a twin's value beyond float's range agrees with the same infinity.
bool twin_agrees(double glsl, double twin, const double* x, int width);

// The GLSL of every user's encoding among `encodings` against its twin on `rows` rows of data:
// raw x (rows x inputs) and the twin's encoding of them (rows x encoded width), as the cpu
// backend trains on. The definition's sample inputs cannot reach every value a dataset holds (a
// world position, a varied parameter of 1000). Throws naming the definition's line, the row
// (`what` N: "training row 17"), its input and both values.
void check_on_rows(const std::vector<InputEncoding>& encodings, int inputs, const float* x, const float* encoded,
                   std::size_t rows, const char* what);

}  // namespace sn::nn

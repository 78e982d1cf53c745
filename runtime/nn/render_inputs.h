// What a network reads when it renders over a G-buffer, shared by both renderers (the fragment
// shader, nn/mlp_render.h, and the cpu kernels, nn/cpu_render.h): the checks a person can fail
// before any work, and the input vector's plan.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "nn/mlp.h"
#include "scene/gbuffer.h"

namespace sn::nn {

// One number of the input vector: component `component` of attribute `attribute` (an index into
// RenderInputs::attributes), or a condition's value when attribute < 0.
struct InputSlot {
  int attribute = -1, component = 0;
  float value = 0;
};

struct RenderInputs {
  std::vector<std::string> attributes;  // G-buffer attributes read, in input order (no conditions)
  std::vector<float> conditions;        // each condition's value, in net.conditions order
  std::vector<InputSlot> slots;         // net.spec.inputs of them, in input order
};

// Throws before any work when the network does not draw a colour (3 outputs), does not name
// its inputs, reads attributes `g` lacks, reads only conditions, or when `values` names
// something that is not a condition. A condition takes its value from `values`, else from the
// network (Condition::value).
RenderInputs render_inputs(const Mlp& net, const scene::GBuffer& g, const std::map<std::string, double>& values = {});

}  // namespace sn::nn

-- expect: mlp_unknown_output_activation\.lua:3: unknown output_activation 'softmax' \(valid: linear, tanh, sigmoid, relu, leaky_relu, sine, softplus, squareplus, elu, gelu, swish, silu, exponential\)
local sn = require "shadenet"
local net = sn.mlp { inputs = 6, hidden = {8}, outputs = 3, output_activation = "softmax" }

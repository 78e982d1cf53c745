-- expect: mlp_unknown_activation\.lua:3: unknown activation 'gaussian' \(valid: tanh, sigmoid, relu, leaky_relu, sine, softplus, squareplus, elu, gelu, swish, silu, exponential\)
local sn = require "shadenet"
local net = sn.mlp { inputs = 6, hidden = {8}, outputs = 3, activation = "gaussian" }

-- expect: mlp_unknown_activation\.lua:3: unknown activation 'gelu' \(valid: linear, tanh, sigmoid, relu, leaky_relu\)
local sn = require "shadenet"
local net = sn.mlp { inputs = 6, hidden = {8}, outputs = 3, activation = "gelu" }

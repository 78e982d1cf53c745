-- expect: mlp_linear_hidden\.lua:3: activation 'linear' cannot be used for hidden layers \(valid: tanh, sigmoid, relu, leaky_relu, sine, softplus, squareplus, elu, gelu, swish, silu, exponential\)
local sn = require "shadenet"
local net = sn.mlp { inputs = 6, hidden = {8}, outputs = 3, activation = "linear" }

-- expect: mlp_nan_weight\.lua:4: layer 1: bias\[2\] must be a finite float, got nan
local sn = require "shadenet"
local net = sn.mlp { inputs = 6, hidden = {8}, outputs = 3 }
net.layers[1].bias[2] = 0 / 0

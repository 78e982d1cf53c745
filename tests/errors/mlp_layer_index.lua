-- expect: mlp_layer_index\.lua:4: layer 4 out of 1\.\.3
local sn = require "shadenet"
local net = sn.mlp { inputs = 6, hidden = {8, 8}, outputs = 3 }
local b = net.layers[4].bias

-- expect: mlp_weight_index\.lua:4: layer 3: weight row 9 out of 1\.\.8
local sn = require "shadenet"
local net = sn.mlp { inputs = 6, hidden = {8, 8, 8}, outputs = 3 }
net.layers[3].weight[9][1] = 0.5

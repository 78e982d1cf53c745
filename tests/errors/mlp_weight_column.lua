-- expect: mlp_weight_column\.lua:4: layer 1: weight\[2\] column 7 out of 1\.\.6
local sn = require "shadenet"
local net = sn.mlp { inputs = 6, hidden = {8}, outputs = 3 }
print(net.layers[1].weight[2][7])

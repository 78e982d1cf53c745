-- expect: mlp_weight_huge\.lua:5: layer 1: weight\[1\]\[1\] must be a finite float, got 1e\+300
local sn = require "shadenet"
local net = sn.mlp { inputs = 2, hidden = { 2 }, outputs = 1 }
-- The number in the message as people read it (it was printed with 300 digits).
net.layers[1].weight[1][1] = 1e300

-- expect: mlp_layer_shape\.lua:4: layer 2: weight: 3 rows of 8 expected, got 2 rows
local sn = require "shadenet"
local net = sn.mlp { inputs = 6, hidden = {8}, outputs = 3 }
net.layers[2].weight = { {1, 2, 3, 4, 5, 6, 7, 8}, {1, 2, 3, 4, 5, 6, 7, 8} }

-- expect: mlp_zero_width\.lua:3: sn\.mlp: hidden layer 2 width must be 1\.\.64, got 0
local sn = require "shadenet"
local net = sn.mlp { inputs = 6, hidden = {8, 0, 8}, outputs = 3 }

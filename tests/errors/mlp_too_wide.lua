-- expect: mlp_too_wide\.lua:3: sn\.mlp: hidden layer 1 width must be 1\.\.64, got 65
local sn = require "shadenet"
local net = sn.mlp { inputs = 6, hidden = {65}, outputs = 3 }

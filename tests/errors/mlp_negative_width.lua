-- expect: mlp_negative_width\.lua:3: sn\.mlp: inputs must be 1\.\.64, got -6
local sn = require "shadenet"
local net = sn.mlp { inputs = -6, hidden = {8}, outputs = 3 }

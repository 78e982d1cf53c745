-- expect: mlp_too_deep\.lua:5: sn\.mlp: number of hidden layers must be 1\.\.32, got 33
local sn = require "shadenet"
local hidden = {}
for i = 1, 33 do hidden[i] = 4 end
local net = sn.mlp { inputs = 6, hidden = hidden, outputs = 3 }

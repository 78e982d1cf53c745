-- expect: mlp_sine_omega\.lua:3: sn\.mlp: sine omega must be in \(0, 10000., got -30
local sn = require "shadenet"
local net = sn.mlp { inputs = 6, hidden = {8}, outputs = 3, activation = "sine", omega = -30 }

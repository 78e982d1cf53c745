-- expect: mlp_forward_nan_buffer\.lua:7: net:forward: buffer row 3 input 5 is infinite
local sn = require "shadenet"
local net = sn.mlp { inputs = 6, hidden = { 4 }, outputs = 3 }
local x = sn.buffer { type = "float32", size = 4 * 6 }
x:fill(0.25)
x:set(2 * 6 + 5, 1 / 0)
net:forward(x)

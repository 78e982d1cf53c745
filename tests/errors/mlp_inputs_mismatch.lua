-- expect: mlp_inputs_mismatch\.lua:7: sn\.train: net 2 \(mlp\(5 -> 8 -> 3, tanh\)\) reads 5 inputs but the dataset has 6 \(normal, view\)
local sn = require "shadenet"
local x, y = {}, {}
for i = 1, 20 do x[i] = {1, 2, 3, 4, 5, i} y[i] = {0, 0, 0} end
local data = sn.dataset { x = x, y = y, input_names = {"normal", "view"} }
local nets = { sn.mlp { inputs = 6, hidden = {8} }, sn.mlp { inputs = 5, hidden = {8} } }
sn.train { nets = nets, data = data, epochs = 1 }

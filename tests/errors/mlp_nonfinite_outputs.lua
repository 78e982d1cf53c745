-- expect: warning: net:forward: 2 of 3 outputs are NaN or infinite \(the first: row 1 output 1\); the weights of mlp\(6 -> 4 -> 3, relu\) may have diverged \(nonfinite = "error" makes this an error, "ignore" silences it\)
-- expect: warning: net:render: [0-9]+ of 1536 pixels are NaN or infinite \(the first: pixel \([0-9]+, [0-9]+\)\)
-- expect: mlp_nonfinite_outputs\.lua:20: net:render: [0-9]+ of 1536 pixels are NaN or infinite \(the first: pixel \([0-9]+, [0-9]+\)\)
-- Weights that overflow float: relu(1e30) times 1e30 is infinite, the difference of two such is
-- NaN. net:forward and scene:render warn (once per network version), a render asked to stops.
local sn = require "shadenet"
local net = sn.mlp { inputs = 6, hidden = { 4 }, outputs = 3, activation = "relu", input_names = { "normal", "view" } }
for j = 1, 4 do net.layers[1].bias[j] = 1e30 end
net.layers[2].weight[1] = { 1e30, 1e30, 0, 0 }
net.layers[2].weight[2] = { 1e30, -1e30, 0, 0 }
local x = { 0.1, 0.2, 0.3, 0.4, 0.5, 0.6 }
local y = net:forward(x)
assert(y[1] == math.huge and y[2] ~= y[2] and y[3] == y[3], "inf, NaN, a finite value")
net:forward(x)  -- the same network again: no second warning
net:forward(x, { nonfinite = "ignore" })
local scene = sn.scene { mesh = "meshes/test_blob.glb", size = { 48, 32 } }
local img = scene:render(net, { nonfinite = "ignore" })
assert(img:size() == 48)
scene:render(net)  -- a warning
scene:render(net, { nonfinite = "error" })

-- expect: mlp_color_mismatch\.lua:6: sn\.train: net 1 \(mlp\(6 -> 8 -> 3, tanh, hsv\)\) learns in colour space hsv but the dataset's targets are rgb
local sn = require "shadenet"
local x, y = {}, {}
for i = 1, 20 do x[i] = {1, 2, 3, 4, 5, i} y[i] = {0, 0, 0} end
local data = sn.dataset { x = x, y = y }
sn.train { nets = { sn.mlp { inputs = 6, hidden = {8}, color = "hsv" } }, data = data }

-- expect: mlp_unknown_backend\.lua:6: sn\.train: unknown backend 'cuda' \(available: auto, cpu
local sn = require "shadenet"
local x, y = {}, {}
for i = 1, 20 do x[i] = {1, 2, 3, 4, 5, i} y[i] = {0, 0, 0} end
local data = sn.dataset { x = x, y = y }
sn.train { nets = { sn.mlp { inputs = 6, hidden = {8} } }, data = data, backend = "cuda" }

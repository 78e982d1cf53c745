-- expect: train_eps_denormal\.lua:6: sn\.train: adam eps must be a normal float, at least 1\.1754944e-38, got 1e-39
local sn = require "shadenet"
local data = sn.dataset { x = { { 0, 1 }, { 1, 0 }, { 1, 1 }, { 0, 0 } }, y = { { 1 }, { 1 }, { 0 }, { 0 } }, split = 0.5 }
local net = sn.mlp { inputs = 2, hidden = { 4 }, outputs = 1 }
-- A denormal eps was 0 in the cpu kernels (they flush denormals): 0/0 at the first step.
sn.train { nets = net, data = data, batch = 2, adam = { eps = 1e-39 } }

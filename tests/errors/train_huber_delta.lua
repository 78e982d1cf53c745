-- expect: train_huber_delta\.lua:5: sn\.train: huber delta must be in \[1e-30, 1e6\], got -0\.5
local sn = require "shadenet"
local data = sn.dataset { x = { { 0, 1 }, { 1, 0 }, { 1, 1 }, { 0, 0 } }, y = { { 1 }, { 1 }, { 0 }, { 0 } }, split = 0.5 }
local net = sn.mlp { inputs = 2, hidden = { 4 }, outputs = 1 }
sn.train { nets = net, data = data, batch = 2, loss = { "huber", delta = -0.5 } }

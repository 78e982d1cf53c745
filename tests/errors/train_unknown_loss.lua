-- expect: train_unknown_loss\.lua:5: sn\.train: unknown loss 'l3' \(valid: l2, l1, relative_l2, huber\)
local sn = require "shadenet"
local data = sn.dataset { x = { { 0, 1 }, { 1, 0 }, { 1, 1 }, { 0, 0 } }, y = { { 1 }, { 1 }, { 0 }, { 0 } }, split = 0.5 }
local net = sn.mlp { inputs = 2, hidden = { 4 }, outputs = 1 }
sn.train { nets = net, data = data, batch = 2, loss = "l3" }

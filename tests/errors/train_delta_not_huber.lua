-- expect: train_delta_not_huber\.lua:6: sn\.train option 'loss': only huber takes a delta
-- A delta on another loss is refused even at huber's default of 1 (it was taken and ignored).
local sn = require "shadenet"
local data = sn.dataset { x = { { 0, 1 }, { 1, 0 }, { 1, 1 }, { 0, 0 } }, y = { { 1 }, { 1 }, { 0 }, { 0 } }, split = 0.5 }
local net = sn.mlp { inputs = 2, hidden = { 4 }, outputs = 1 }
sn.train { nets = net, data = data, batch = 2, loss = { "l2", delta = 1 } }

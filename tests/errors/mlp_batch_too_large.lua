-- expect: mlp_batch_too_large\.lua:6: sn\.train: batch 32 is larger than the training set \(16 rows\)
local sn = require "shadenet"
local x, y = {}, {}
for i = 1, 20 do x[i] = {1, 2, 3, 4, 5, i} y[i] = {0, 0, 0} end
local data = sn.dataset { x = x, y = y, split = 0.8 }
sn.train { nets = { sn.mlp { inputs = 6, hidden = {8} } }, data = data, batch = 32 }

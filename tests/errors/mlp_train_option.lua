-- expect: mlp_train_option\.lua:6: sn\.train: unknown option 'epoch' \(valid: nets, data, epochs, batch, adam, seed, backend, keep, progress, tick, tick_seconds, loss, divergence_factor\)
local sn = require "shadenet"
local x, y = {}, {}
for i = 1, 20 do x[i] = {1, 2, 3, 4, 5, i} y[i] = {0, 0, 0} end
local data = sn.dataset { x = x, y = y }
sn.train { nets = { sn.mlp { inputs = 6, hidden = {8} } }, data = data, epoch = 3 }

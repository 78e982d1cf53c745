-- expect: train_epochs_wrap\.lua:8: sn\.train option 'epochs': integer within \+-\(2\^31 - 1\) expected, got 4294967297
local sn = require "shadenet"

-- 2^32 + 1 epochs used to wrap to 1: one epoch trained, and no word.
local data = sn.dataset { x = { { 0, 0 }, { 1, 1 }, { 0, 1 }, { 1, 0 } }, y = { { 0 }, { 1 }, { 1 }, { 0 } },
                          inputs = 2, outputs = 1, split = 0.5 }
local net = sn.mlp { inputs = 2, hidden = { 4 }, outputs = 1 }
sn.train { nets = { net }, data = data, epochs = 2 ^ 32 + 1 }

-- expect: sn\.train: divergence_factor must be >= 1 \(math\.huge turns the rule off\), got 0\.5
local sn = require "shadenet"
local data = sn.dataset { x = { { 0 }, { 1 }, { 2 }, { 3 } }, y = { { 0 }, { 1 }, { 2 }, { 3 } }, split = 0.5 }
sn.train { nets = sn.mlp { inputs = 1, hidden = { 4 }, outputs = 1 }, data = data, batch = 1, divergence_factor = 0.5 }

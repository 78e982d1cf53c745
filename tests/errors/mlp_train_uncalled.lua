-- expect: mlp_train_uncalled\.lua:6: sn\.train option 'nets': element 1 is the function sn\.mlp \(call it: sn\.mlp {\.\.\.}\), not an Mlp
-- Any object's constructor passed uncalled is named, wherever an object of a type is checked.
local sn = require "shadenet"

local data = sn.dataset { x = { { 0, 0, 0, 0, 0, 1 } }, y = { { 0, 0, 0 } } }
sn.train { nets = { sn.mlp }, data = data, epochs = 1 }

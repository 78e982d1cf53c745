-- expect: dataset_concat_names\.lua:6: sn\.dataset\.concat: dataset 2 has inputs {view, normal}, dataset 1 has {normal, view}
local sn = require "shadenet"
local y = { { 1, 0, 0 }, { 0, 1, 0 } }
local a = sn.dataset { x = { { 0, 0, 1, 0, 0, 1 }, { 0, 1, 0, 0, 0, 1 } }, y = y, input_names = { "normal", "view" } }
local b = sn.dataset { x = { { 0, 0, 1, 0.5, 0.5, 0 }, { 0, 1, 0, 0.5, 0, 0 } }, y = y, input_names = { "view", "normal" } }
sn.dataset.concat { a, b }

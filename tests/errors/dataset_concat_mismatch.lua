-- expect: dataset_concat_mismatch\.lua:6: sn\.dataset\.concat: dataset 2 has 1 outputs, dataset 1 has 3
local sn = require "shadenet"
local x = { { 0, 0, 1 }, { 0, 1, 0 }, { 1, 0, 0 } }
local rgb = sn.dataset { x = x, y = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } } }
local grey = sn.dataset { x = x, y = { { 0.2 }, { 0.5 }, { 0.8 } } }
local both = sn.dataset.concat { rgb, grey }

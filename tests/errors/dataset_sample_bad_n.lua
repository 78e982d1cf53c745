-- expect: dataset_sample_bad_n\.lua:5: sn\.dataset\.sample option 'n' must be a whole number in 2\.\.16777216 \(rows, training and validation together\), got 64149\.5
local sn = require "shadenet"

-- Rows come whole.
local data = sn.dataset.sample { target = sn.lighting.phong {}, n = 64149.5 }

-- expect: dataset_sample_textured\.lua:5: sn\.dataset\.sample: lighting model textured_phong reads the attribute 'base_color', which a sampled \(normal, view\) pair has not: build its dataset from a mesh with scene:dataset\{\.\.\.\}
local sn = require "shadenet"

-- A sampled (normal, view) has no texture to read a base colour from.
local data = sn.dataset.sample { target = sn.lighting.textured_phong {}, n = 100 }

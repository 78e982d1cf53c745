-- expect: dataset_sample_textured\.lua:5: sn\.dataset\.sample: lighting model textured_phong reads a base colour from a texture, which a sampled direction has not: build its dataset from a textured mesh with scene:dataset\{\.\.\.\}
local sn = require "shadenet"

-- A sampled (normal, view) has no texture to read a base colour from.
local data = sn.dataset.sample { target = sn.lighting.textured_phong {}, n = 100 }

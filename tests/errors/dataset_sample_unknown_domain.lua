-- expect: dataset_sample_unknown_domain\.lua:5: sn\.dataset\.sample option 'normals': unknown normals domain 'cube' \(valid: sphere, hemisphere, lit\)
local sn = require "shadenet"

-- Normals are drawn over a sphere, a hemisphere or the lit hemisphere; a cube is not a domain.
local data = sn.dataset.sample { target = sn.lighting.ggx {}, normals = "cube" }

-- expect: dataset_unknown_option\.lua:5: scene:dataset: unknown option 'colour' \(valid: inputs, target, color, views, poses, split, seed, samples, vary\)
local sn = require "shadenet"

local scene = sn.scene { mesh = "meshes/test_blob.glb", size = { 32, 32 } }
local data = scene:dataset { target = sn.lighting.phong {}, colour = "hsv" }

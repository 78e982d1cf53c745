-- expect: dataset_bad_split\.lua:5: dataset split must lie strictly between 0 and 1 \(the training share\), got 1\.2
local sn = require "shadenet"

local scene = sn.scene { mesh = "meshes/test_blob.glb", size = { 32, 32 } }
local data = scene:dataset { target = sn.lighting.phong {}, split = 1.2 }

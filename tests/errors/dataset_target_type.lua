-- expect: dataset_target_type\.lua:5: Lighting expected, got string
local sn = require "shadenet"

local scene = sn.scene { mesh = "meshes/test_blob.glb", size = { 32, 32 } }
local data = scene:dataset { target = "phong" }

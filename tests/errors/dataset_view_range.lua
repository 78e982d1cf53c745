-- expect: dataset_view_range\.lua:5: scene:dataset option 'views': view 9 is outside the scene's views 1\.\.8
local sn = require "shadenet"

local scene = sn.scene { mesh = "meshes/test_blob.glb", size = { 32, 32 } }
local data = scene:dataset { target = sn.lighting.phong {}, views = { 1, 9 } }

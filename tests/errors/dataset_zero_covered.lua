-- expect: dataset_zero_covered\.lua:7: the dataset has no covered pixels: the mesh is outside every camera view \(1 view of 64x64\)
local sn = require "shadenet"

-- A camera that looks away from the mesh.
local away = sn.camera { eye = { 0, 0, 5 }, target = { 0, 0, 10 } }
local scene = sn.scene { mesh = "meshes/test_blob.glb", size = { 64, 64 }, views = { away } }
local data = scene:dataset { target = sn.lighting.phong {} }

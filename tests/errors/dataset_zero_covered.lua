-- expect: dataset_zero_covered\.lua:7: the dataset has no covered pixels: the mesh covers no pixel centre in any camera view \(1 view of 64x64\): it is outside them, or too small or flat \(zero area\) to cover a pixel
local sn = require "shadenet"

-- A camera that looks away from the mesh.
local away = sn.camera { eye = { 0, 0, 5 }, target = { 0, 0, 10 } }
local scene = sn.scene { mesh = "meshes/test_blob.glb", size = { 64, 64 }, views = { away } }
local data = scene:dataset { target = sn.lighting.phong {} }

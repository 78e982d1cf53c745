-- expect: dataset_no_texture\.lua:6: attribute 'base_color': mesh 'meshes/test_blob.glb' has no base-colour texture
local sn = require "shadenet"

-- textured_phong reads the mesh's base-colour texture; the blob has none.
local scene = sn.scene { mesh = "meshes/test_blob.glb", size = { 32, 32 } }
local data = scene:dataset { target = sn.lighting.textured_phong {} }

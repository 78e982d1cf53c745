-- expect: dataset_uv_on_box\.lua:6: attribute 'uv': mesh '.*Box\.gltf' has no texture coordinates \(TEXCOORD_0\)
local sn = require "shadenet"

-- Box.gltf has positions and normals but no UVs.
local scene = sn.scene { mesh = "../shared/meshes/Box.gltf", size = { 32, 32 } }
local data = scene:dataset { inputs = { "position", "uv" }, target = sn.lighting.phong {} }

-- expect: dataset_unknown_input\.lua:5: unknown G-buffer attribute 'normals' \(valid: normal, view, position, world_position, uv, base_color, tangent, bitangent\)
local sn = require "shadenet"

local scene = sn.scene { mesh = "meshes/test_blob.glb", size = { 32, 32 } }
local data = scene:dataset { inputs = { "normals", "view" }, target = sn.lighting.phong {} }

-- expect: dataset_render_wrong_type\.lua:5: scene:render: a lighting model \(sn\.lighting\.\*\) or a network \(sn\.mlp\) expected, got string
local sn = require "shadenet"

local scene = sn.scene { mesh = "meshes/test_blob.glb", size = { 32, 32 } }
local img = scene:render("phong")

-- expect: coverage_no_normal_input\.lua:6: ds:coverage: the dataset's inputs are \{"position", "view"\} \(6 numbers\); coverage needs inputs named "normal" and "view" \(3 numbers each\)
local sn = require "shadenet"

local scene = sn.scene { mesh = "meshes/test_blob.glb", size = { 32, 32 }, views = { count = 1 } }
local data = scene:dataset { inputs = { "position", "view" }, target = sn.lighting.phong {}, samples = 100 }
local c = data:coverage()

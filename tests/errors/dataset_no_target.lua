-- expect: dataset_no_target\.lua:5: scene:dataset option 'target' is required \(a lighting model, e\.g\. sn\.lighting\.phong\{\}\)
local sn = require "shadenet"

local scene = sn.scene { mesh = "meshes/test_blob.glb", size = { 32, 32 } }
local data = scene:dataset { inputs = { "normal", "view" } }

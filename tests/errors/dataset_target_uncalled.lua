-- expect: dataset_target_uncalled\.lua:6: scene:dataset option 'target': a lighting model \(sn\.lighting\.\*{\.\.\.}\) expected, got the function sn\.lighting\.ggx \(call it: sn\.lighting\.ggx {\.\.\.}, or sn\.lighting\.ggx {} for its defaults\)
-- A model's constructor left uncalled (target = sn.lighting.ggx): the error names it and says how to call it.
local sn = require "shadenet"

local scene = sn.scene { mesh = "meshes/test_blob.glb", size = { 32, 32 } }
local data = scene:dataset { target = sn.lighting.ggx }

-- expect: dataset_target_type\.lua:6: scene:dataset option 'target': a lighting model \(sn\.lighting\.\*{\.\.\.}\) expected, got the string 'phong' \(sn\.lighting\.phong {} makes that model, or sn\.lighting\.new\("phong", {\.\.\.}\)\)
-- A model's name where the model belongs: the error says how to make it.
local sn = require "shadenet"

local scene = sn.scene { mesh = "meshes/test_blob.glb", size = { 32, 32 } }
local data = scene:dataset { target = "phong" }

-- expect: lighting_check_name\.lua:5: sn\.lighting\.stress model: a lighting model \(sn\.lighting\.\*{\.\.\.}\) expected, got the string 'phong' \(sn\.lighting\.phong {} makes that model, or sn\.lighting\.new\("phong", {\.\.\.}\)\)
-- A model's name where sn.lighting.check or sn.lighting.stress takes the model: the error says how to make it.
local sn = require "shadenet"

sn.lighting.stress("phong")

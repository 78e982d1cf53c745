-- expect: lighting_unknown_color_space\.lua:5: unknown colour space 'lab' \(valid: rgb, hsv, cie, cie_xyz, cie_lab\)
local sn = require "shadenet"

local scene = sn.scene { mesh = "meshes/test_blob.glb", size = { 32, 32 } }
local data = scene:dataset { target = sn.lighting.ggx {}, color = "lab" }

-- expect: lighting_zero_light\.lua:4: sn\.scene option 'light': light 'dir' must be a non-zero, finite direction towards the light, got \{0, 0, 0\}
local sn = require "shadenet"

local scene = sn.scene { mesh = "meshes/test_blob.glb", light = { dir = { 0, 0, 0 } } }

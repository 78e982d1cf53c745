-- expect: mesh_camera_same_point\.lua:4: camera: eye and target are the same point
local sn = require "shadenet"

local c = sn.camera { eye = { 1, 2, 3 }, target = { 1, 2, 3 } }

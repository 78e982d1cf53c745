-- expect: mesh_draw_missing_camera\.lua:7: sn\.draw option 'camera' is required \(a Camera\)
local sn = require "shadenet"

local t = sn.target { width = 8, height = 8 }
local p = sn.program { vertex = "mesh.vert", fragment = "normals.frag" }
local m = sn.mesh.sphere()
sn.draw { target = t, program = p, mesh = m }

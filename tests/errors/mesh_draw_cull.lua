-- expect: mesh_draw_cull\.lua:8: unknown sn\.draw option 'cull' 'both' \(valid: none, back, front\)
local sn = require "shadenet"

local t = sn.target { width = 8, height = 8 }
local p = sn.program { vertex = "mesh.vert", fragment = "normals.frag" }
local m = sn.mesh.sphere()
local c = sn.camera {}
sn.draw { target = t, program = p, mesh = m, camera = c, cull = "both" }

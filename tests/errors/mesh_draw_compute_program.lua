-- expect: mesh_draw_compute_program\.lua:8: sn\.draw option 'program': examples/square\.comp is a compute program; sn\.draw needs vertex \+ fragment
local sn = require "shadenet"

local t = sn.target { width = 8, height = 8 }
local p = sn.program { compute = "examples/square.comp", defines = { LOCAL_SIZE = 64 } }
local m = sn.mesh.sphere()
local c = sn.camera {}
sn.draw { target = t, program = p, mesh = m, camera = c }

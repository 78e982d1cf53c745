-- expect: mesh_draw_wrong_type\.lua:7: sn\.draw option 'mesh': Mesh expected, got string
local sn = require "shadenet"

local t = sn.target { width = 8, height = 8 }
local p = sn.program { vertex = "mesh.vert", fragment = "normals.frag" }
local c = sn.camera {}
sn.draw { target = t, program = p, mesh = "Duck.gltf", camera = c }

-- expect: mesh_missing\.lua:4: cannot read mesh file 'no/such/duck\.gltf': no such file
local sn = require "shadenet"

local duck = sn.mesh.load("no/such/duck.gltf")

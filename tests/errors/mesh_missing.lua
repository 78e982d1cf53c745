-- expect: mesh_missing\.lua:4: mesh file 'no/such/duck\.gltf': does not exist
local sn = require "shadenet"

local duck = sn.mesh.load("no/such/duck.gltf")

-- expect: mesh_missing\.lua:5: cannot read mesh file 'no/such/duck\.gltf': no such file \(relative to the working directory /[^)]*\)
-- A relative path names the directory it was looked for in (tests run from the repository).
local sn = require "shadenet"

local duck = sn.mesh.load("no/such/duck.gltf")

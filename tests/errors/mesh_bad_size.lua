-- expect: mesh_bad_size\.lua:4: sphere: rings must be 2\.\.4096, got 1
local sn = require "shadenet"

local s = sn.mesh.sphere { rings = 1 }

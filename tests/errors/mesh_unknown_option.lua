-- expect: mesh_unknown_option\.lua:4: sn\.mesh\.sphere: unknown option 'segs' \(valid: radius, segments, rings\)
local sn = require "shadenet"

local s = sn.mesh.sphere { radius = 1, segs = 32 }

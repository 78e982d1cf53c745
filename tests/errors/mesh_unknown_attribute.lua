-- expect: mesh_unknown_attribute\.lua:5: unknown mesh attribute 'tangent' \(valid: normal, uv, texture\)
local sn = require "shadenet"

local s = sn.mesh.sphere()
print(s:has("tangent"))

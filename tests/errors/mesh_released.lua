-- expect: mesh_released\.lua:6: this Mesh was released; it can no longer be used
local sn = require "shadenet"

local s = sn.mesh.sphere()
s:release()
print(s:counts())

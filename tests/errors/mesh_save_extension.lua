-- expect: mesh_save_extension\.lua:6: mesh:save: 'out/errors/sphere\.gltf' must end in \.glb
-- then-missing: out/errors/sphere.gltf
local sn = require "shadenet"

local s = sn.mesh.sphere()
s:save("out/errors/sphere.gltf")

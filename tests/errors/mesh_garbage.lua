-- expect: mesh_garbage\.lua:4: mesh file 'tests/data/garbage\.gltf': is neither a glTF JSON file
local sn = require "shadenet"

local m = sn.mesh.load("tests/data/garbage.gltf")

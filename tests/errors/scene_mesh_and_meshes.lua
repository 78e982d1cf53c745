-- expect: scene_mesh_and_meshes\.lua:3: sn\.scene: give 'mesh' or 'meshes', not both
local sn = require "shadenet"
local scene = sn.scene { mesh = "meshes/cloth.glb", meshes = { "meshes/test_blob.glb" } }

-- expect: scene_pose_singular\.lua:4: sn\.scene option 'poses' element 1: the transform is singular \(its 3x3 part has determinant 0\), so it would flatten the mesh
local sn = require "shadenet"
-- A zero scale along y squashes the cloth flat.
local scene = sn.scene { mesh = "meshes/cloth.glb", poses = { { scale = { 1, 0, 1 } } } }

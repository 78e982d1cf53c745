-- expect: scene_pose_projective\.lua:5: sn\.scene option 'poses' element 1: the last row must be 0 0 0 1 \(an affine transform\), got 0 0 1 0
local sn = require "shadenet"
-- A projection matrix is not a pose.
local m = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0 }
local scene = sn.scene { mesh = "meshes/cloth.glb", poses = { m } }

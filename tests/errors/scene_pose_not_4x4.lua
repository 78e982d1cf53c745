-- expect: scene_pose_not_4x4\.lua:5: sn\.scene option 'poses' element 2: a 4x4 transform \(4 rows of 4 numbers, or 16 numbers row by row\) or \{ rotate = \{degrees, x, y, z\}, scale = \.\.\., translate = \{x, y, z\}, about = \{x, y, z\} \} expected \(it has 3 elements\)
local sn = require "shadenet"
-- A 3x3 rotation where a 4x4 transform belongs.
local rot = { { 1, 0, 0 }, { 0, 0, -1 }, { 0, 1, 0 } }
local scene = sn.scene { mesh = "meshes/cloth.glb", poses = { {}, rot } }

-- expect: scene_mesh_too_small\.lua:5: .*the meshes are too small to frame: their bounding sphere's radius is [0-9.]+e-30, below 1e-6
local sn = require "shadenet"
-- A sphere of radius 1e-30 was framed as if it were 1e-6: a blank picture, no word.
local tiny = sn.mesh.sphere { radius = 1e-30, segments = 8, rings = 4 }
sn.scene { mesh = tiny, size = { 32, 32 }, views = { count = 1 } }

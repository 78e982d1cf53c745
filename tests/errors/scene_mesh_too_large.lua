-- expect: scene_mesh_too_large\.lua:5: .*the meshes are too large to frame: the camera would stand 1\.[0-9]+e\+39 from their centre
local sn = require "shadenet"
-- A sphere of radius 3e38: its camera stood beyond float's range, and every picture was blank.
local big = sn.mesh.sphere { radius = 3e38, segments = 8, rings = 4 }
sn.scene { mesh = big, size = { 32, 32 }, views = { count = 1 } }

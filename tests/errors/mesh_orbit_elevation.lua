-- expect: mesh_orbit_elevation\.lua:4: orbit: elevation must be in \(-90, 90\) degrees, got 90
local sn = require "shadenet"

local cams = sn.orbit { count = 4, elevation = 90 }

-- expect: scene_mesh_too_small\.lua:7: .*the meshes are too small to frame: their bounding sphere's radius is [0-9.]+e-30, below 1e-6
-- expect: below 1e-6; scale them up by [0-9.]+e\+29 to a radius of 1: mesh:transformed. scale = [0-9.]+e\+29 }
local sn = require "shadenet"
-- A sphere of radius 1e-30 was framed as if it were 1e-6: a blank picture, no word. The error
-- names the scale that frames it (tests/lua/test_scene_tiny_mesh.lua applies it).
local tiny = sn.mesh.sphere { radius = 1e-30, segments = 8, rings = 4 }
sn.scene { mesh = tiny, size = { 32, 32 }, views = { count = 1 } }

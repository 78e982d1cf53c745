-- expect: camera_ray_outside\.lua:6: camera:ray: pixel \(0, 1\) is outside the 64 x 32 image \(x in 0\.5\.\.64\.5, y in 0\.5\.\.32\.5; whole numbers are pixel centres\)
-- A 0-based pixel (or x for y) is an error, not a ray through a point beside the image.
local sn = require "shadenet"

local cam = sn.camera {}
print(cam:ray(0, 1, 64, 32))

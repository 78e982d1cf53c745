-- Meshes too small to frame: the error says how far to scale them up, and doing what it says
-- frames them; a view ring given a distance takes its near and far planes from the meshes it
-- frames (they were set for a radius of at least 1e-6, which a camera then refused).
local sn = require "shadenet"

-- The covered pixels of view 1 and whether every covered normal is a unit vector.
local function covered(scene)
  local g = scene:gbuffer { attributes = { "normal" } }
  local img = g:read("normal")
  local w, h = img:size()
  for y = 1, h do
    for x = 1, w do
      local p = img:get(x, y)
      if p[4] > 0.5 then
        local len = math.sqrt(p[1] ^ 2 + p[2] ^ 2 + p[3] ^ 2)
        assert(math.abs(len - 1) < 1e-3, ("normal of length %g at pixel %d, %d"):format(len, x, y))
      end
    end
  end
  return g:covered()
end

-- 1. A sphere of radius 1e-20: the advice is a scale, and that scale frames it.
local tiny = sn.mesh.sphere { segments = 16, rings = 8 }:transformed { scale = 1e-20 }
local ok, err = pcall(sn.scene, { mesh = tiny, size = { 32, 32 }, views = { count = 1 } })
assert(not ok, "a sphere of radius 1e-20 is too small to frame")
err = tostring(err)
local factor = tonumber(err:match("mesh:transformed{ scale = ([^ ]+) }"))
assert(factor, "the error names a scale to apply: " .. err)
assert(not err:find("distance", 1, true), "no advice that leads to another error: " .. err)
local scaled = tiny:transformed { scale = factor }
local lo, hi = scaled:bounds()
local radius = 0.5 * math.sqrt((hi[1] - lo[1]) ^ 2 + (hi[2] - lo[2]) ^ 2 + (hi[3] - lo[3]) ^ 2)
assert(math.abs(radius - 1) < 1e-3, "the scale brings the radius to 1, got " .. radius)
local n = covered(sn.scene { mesh = scaled, size = { 32, 32 }, views = { count = 1 } })
assert(n > 100, "the scaled sphere is framed: " .. n .. " pixels covered")

-- 2. A sphere of radius 1e-11 seen from 4e-11: the camera's near and far planes bracket it.
local small = sn.mesh.sphere { segments = 16, rings = 8 }:transformed { scale = 1e-11 }
n = covered(sn.scene { mesh = small, size = { 32, 32 }, views = { count = 1, distance = 4e-11 } })
assert(n > 100, "the small sphere is in view: " .. n .. " pixels covered")
print("ok")

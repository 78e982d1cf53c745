-- Generates the meshes shadenet's experiments train and test on (run from the repository root):
--   build/shadenet meshes/make_meshes.lua [out_dir]
-- cloth.glb      the training mesh: a shirt-front-like sheet wrapped around a torso, with
--                vertical folds that deepen towards the hem, diagonal drag wrinkles under the
--                shoulders, a sag and fine wrinkles at the hem (the thesis trained on a clothing
--                mesh); smooth normals from the surface's partial derivatives, UVs across the
--                sheet and a woven fabric texture with a zipper and darker cuffs (for the
--                textured experiments of section 4.5).
-- test_blob.glb  a different shape for testing: a sphere with smooth bumps.
local sn = require "shadenet"

local out = arg[1] or "meshes"
local pi, sin, cos, exp, sqrt, floor = math.pi, math.sin, math.cos, math.exp, math.sqrt, math.floor

-- Central differences of a parametric surface: accurate to ~1e-9 here, and free of the
-- faceting that triangle-averaged normals would add along the folds.
local function partials(surface, u, v)
  local h = 1e-5
  local ax, ay, az = surface(u + h, v)
  local bx, by, bz = surface(u - h, v)
  local cx, cy, cz = surface(u, v + h)
  local dx, dy, dz = surface(u, v - h)
  return (ax - bx) / (2 * h), (ay - by) / (2 * h), (az - bz) / (2 * h),
         (cx - dx) / (2 * h), (cy - dy) / (2 * h), (cz - dz) / (2 * h)
end

local function normalize(x, y, z)
  local l = sqrt(x * x + y * y + z * z)
  return x / l, y / l, z / l
end

---------------------------------------------------------------------------------------------
-- The cloth. u in [0, 1] runs around the torso (left to right seen from the front, +Z),
-- v in [0, 1] from the collar down to the hem.
local function fold_depth(u, v)
  local vertical = 0.035 * (0.3 + v) * sin(2 * pi * 6 * u + 1.3 * sin(2 * pi * v))
  local drag = 0.014 * sin(2 * pi * (4 * u + 3 * v) + 0.5) * exp(-((v - 0.3) / 0.22) ^ 2)
  local hem = 0.008 * sin(2 * pi * 15 * u) * v * v
  local sag = 0.02 * sin(2 * pi * 2.5 * v) * (1 - (2 * u - 1) ^ 2)
  return vertical + drag + hem + sag
end

local function cloth_surface(u, v)
  local theta = (u - 0.5) * 2.4          -- about +-69 degrees around the torso
  local r = 0.55 + 0.08 * v + fold_depth(u, v)  -- flares a little towards the hem
  return r * sin(theta), 0.8 - 1.6 * v, r * cos(theta)
end

-- A woven fabric: a twill of diagonal threads, a faint plaid, a zipper down the middle and
-- darker cuffs along the hem. Values as stored (no transfer curve), like every shadenet image.
local function fabric(size)
  local img = sn.image.new { width = size, height = size, channels = 4 }
  for y = 1, size do
    local v = (y - 0.5) / size
    for x = 1, size do
      local u = (x - 0.5) / size
      local twill = 0.5 + 0.5 * sin(2 * pi * (x + y) / 6)
      local plaid = (floor(u * 8) + floor(v * 8)) % 2
      local r, g, b = 0.20 + 0.06 * twill, 0.30 + 0.07 * twill + 0.05 * plaid, 0.55 + 0.10 * twill + 0.08 * plaid
      if math.abs(u - 0.5) < 0.012 then  -- the zipper: light metal teeth on a dark tape
        local tooth = floor(v * size / 3) % 2
        r, g, b = 0.15 + 0.6 * tooth, 0.15 + 0.55 * tooth, 0.15 + 0.4 * tooth
      elseif v > 0.9 then                -- the cuff band
        r, g, b = r * 0.45, g * 0.45, b * 0.5
      end
      img:set(x, y, { r, g, b, 1 })
    end
  end
  return img
end

local function grid_mesh(name, surface, nu, nv, outward, texture)
  local positions, normals, uvs, indices = {}, {}, {}, {}
  for j = 0, nv do
    local v = j / nv
    for i = 0, nu do
      local u = i / nu
      local x, y, z = surface(u, v)
      local ux, uy, uz, vx, vy, vz = partials(surface, u, v)
      -- dP/dv x dP/du points out of the front (+Z) for this parametrisation.
      local nx, ny, nz = normalize(vy * uz - vz * uy, vz * ux - vx * uz, vx * uy - vy * ux)
      if not outward then nx, ny, nz = -nx, -ny, -nz end
      positions[#positions + 1], positions[#positions + 2], positions[#positions + 3] = x, y, z
      normals[#normals + 1], normals[#normals + 2], normals[#normals + 3] = nx, ny, nz
      uvs[#uvs + 1], uvs[#uvs + 2] = u, v
    end
  end
  local row = nu + 1
  for j = 0, nv - 1 do
    for i = 0, nu - 1 do
      local a = j * row + i + 1          -- 1-based: a top-left, b top-right, c below a, d below b
      local b, c, d = a + 1, a + row, a + row + 1
      -- counter-clockwise seen from the front
      indices[#indices + 1], indices[#indices + 2], indices[#indices + 3] = a, c, b
      indices[#indices + 1], indices[#indices + 2], indices[#indices + 3] = b, c, d
    end
  end
  return sn.procedural_mesh { name = name, positions = positions, normals = normals, uvs = uvs,
                              indices = indices, texture = texture }
end

---------------------------------------------------------------------------------------------
-- The test blob: r(d) = f(d) for unit directions d, f smooth on the sphere. Its normal is
-- f d - grad_s f (the surface gradient of f), so no finite differences are needed.
local function bump(x, y, z)
  local f = 1 + 0.07 * sin(5 * x + 1) * sin(4 * y) * sin(6 * z + 2) + 0.05 * sin(3 * x - 2 * z) * cos(5 * y)
  local gx = 0.07 * 5 * cos(5 * x + 1) * sin(4 * y) * sin(6 * z + 2) + 0.05 * 3 * cos(3 * x - 2 * z) * cos(5 * y)
  local gy = 0.07 * 4 * sin(5 * x + 1) * cos(4 * y) * sin(6 * z + 2) - 0.05 * 5 * sin(3 * x - 2 * z) * sin(5 * y)
  local gz = 0.07 * 6 * sin(5 * x + 1) * sin(4 * y) * cos(6 * z + 2) - 0.05 * 2 * cos(3 * x - 2 * z) * cos(5 * y)
  return f, gx, gy, gz
end

local function blob(segments, rings)
  local positions, normals, uvs, indices = {}, {}, {}, {}
  for j = 0, rings do
    local phi = pi * j / rings                    -- from the north pole (+Y)
    for i = 0, segments do
      local theta = 2 * pi * i / segments         -- from +Z towards +X
      local dx, dy, dz = sin(phi) * sin(theta), cos(phi), sin(phi) * cos(theta)
      local f, gx, gy, gz = bump(dx, dy, dz)
      local gd = gx * dx + gy * dy + gz * dz     -- remove the radial part: the surface gradient
      local sx, sy, sz = gx - gd * dx, gy - gd * dy, gz - gd * dz
      local nx, ny, nz = normalize(f * dx - sx, f * dy - sy, f * dz - sz)
      positions[#positions + 1], positions[#positions + 2], positions[#positions + 3] = f * dx, f * dy, f * dz
      normals[#normals + 1], normals[#normals + 2], normals[#normals + 3] = nx, ny, nz
      uvs[#uvs + 1], uvs[#uvs + 2] = i / segments, j / rings
    end
  end
  local row = segments + 1
  for j = 0, rings - 1 do
    for i = 0, segments - 1 do
      local a = j * row + i + 1
      local b, c, d = a + 1, a + row, a + row + 1
      -- counter-clockwise seen from outside; the pole rows' degenerate triangles are skipped
      if j > 0 then indices[#indices + 1], indices[#indices + 2], indices[#indices + 3] = a, c, b end
      if j < rings - 1 then indices[#indices + 1], indices[#indices + 2], indices[#indices + 3] = b, c, d end
    end
  end
  return sn.procedural_mesh { name = "test_blob", positions = positions, normals = normals, uvs = uvs,
                              indices = indices }
end

local cloth = grid_mesh("cloth", cloth_surface, 120, 150, true, fabric(256))
print(cloth, cloth:save(out .. "/cloth.glb"))
local test = blob(96, 64)
print(test, test:save(out .. "/test_blob.glb"))

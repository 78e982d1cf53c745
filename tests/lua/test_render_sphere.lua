-- Renders a tessellated sphere's normal map and checks every pixel against the analytic
-- surface: the ray through each pixel centre (camera:ray) either hits the true surface, and then
-- the rendered normal must match the true normal there, or misses it, and then the pixel must be
-- uncovered (alpha 0). Only a one-pixel rim along the silhouette may disagree: the tessellation
-- is inscribed in the true surface and the rasteriser samples pixel centres.
--
-- Two renders: (1) the unit sphere, identity model; (2) the same mesh rotated 30 degrees about Z
-- and scaled by (0.8, 0.5, 0.65) into an ellipsoid, which only comes out right when u_normal_matrix
-- is the inverse transpose of the model (a plain model matrix, or a transposed one, tilts the
-- normals by many degrees).
--
-- Tolerance: the interpolated normals of a 256 x 128 sphere differ from the true ones by at most
-- 0.8 degrees on llvmpipe (measured; 4.7 at 64 x 32, 1.4 at 128 x 64, 0.2 at 512 x 256, falling
-- as the tessellation refines); we assert 1.5 degrees.
local sn = require "shadenet"

local W, H = 160, 120            -- not square: a wrong aspect would move the silhouette
local TOLERANCE_DEG = 1.5

local sphere = sn.mesh.sphere { radius = 1, segments = 256, rings = 128 }
local camera = sn.camera { eye = { 1.9, 1.1, 2.6 }, target = { 0.25, -0.1, 0 }, fov = 40, near = 0.5, far = 10 }
local program = sn.program { vertex = "mesh.vert", fragment = "normals.frag" }
local target = sn.target { width = W, height = H }

-- The surface x = c + R S u, |u| = 1 (R about Z by `angle` degrees, S = diag(scale)).
local function surface(c, scale, angle)
  local a = math.rad(angle)
  local co, si = math.cos(a), math.sin(a)
  local s = { surface = true, c = c, scale = scale, co = co, si = si }
  -- column-major model matrix: columns R * (scale_i e_i), then the translation
  s.model = { scale[1] * co, scale[1] * si, 0, 0,  -scale[2] * si, scale[2] * co, 0, 0,
              0, 0, scale[3], 0,  c[1], c[2], c[3], 1 }
  return s
end

-- World vector -> unit-sphere space: S^-1 R^T v.
local function to_unit(s, v)
  return { (s.co * v[1] + s.si * v[2]) / s.scale[1], (-s.si * v[1] + s.co * v[2]) / s.scale[2], v[3] / s.scale[3] }
end
local function dot(a, b) return a[1] * b[1] + a[2] * b[2] + a[3] * b[3] end

-- Unit normal where the ray first meets the surface, or false when it misses.
local function true_normal(s, o, d)
  local ou = to_unit(s, { o[1] - s.c[1], o[2] - s.c[2], o[3] - s.c[3] })
  local du = to_unit(s, d)
  local a, b, c = dot(du, du), dot(ou, du), dot(ou, ou) - 1
  local disc = b * b - a * c
  if disc < 0 then return false end
  local t = (-b - math.sqrt(disc)) / a
  local u = { ou[1] + t * du[1], ou[2] + t * du[2], ou[3] + t * du[3] }
  -- the gradient of |S^-1 R^T (x - c)|^2 is R S^-1 u
  local g = { u[1] / s.scale[1], u[2] / s.scale[2], u[3] / s.scale[3] }
  local n = { s.co * g[1] - s.si * g[2], s.si * g[1] + s.co * g[2], g[3] }
  local len = math.sqrt(dot(n, n))
  return { n[1] / len, n[2] / len, n[3] / len }
end

local function check(name, s)
  sn.draw { target = target, program = program, mesh = sphere, camera = camera, model = s.model,
            clear = { 0, 0, 0, 0 } }
  local img = target:read()
  local truth, covered = {}, {}
  for y = 1, H do
    truth[y], covered[y] = {}, {}
    for x = 1, W do
      truth[y][x] = true_normal(s, camera:ray(x, y, W, H))
      covered[y][x] = img:get(x, y)[4] > 0.5
    end
  end
  -- on the rim: one of the 8 neighbours' rays does the opposite (hit vs miss)
  local function on_rim(x, y)
    local h = truth[y][x] ~= false
    for dy = -1, 1 do
      for dx = -1, 1 do
        local n = truth[y + dy] and truth[y + dy][x + dx]
        if n ~= nil and (n ~= false) ~= h then return true end
      end
    end
    return false
  end

  local n_covered, n_checked, n_rim, max_err, worst = 0, 0, 0, 0, { 0, 0 }
  for y = 1, H do
    for x = 1, W do
      local t, cov = truth[y][x], covered[y][x]
      local rgba = img:get(x, y)
      if cov then n_covered = n_covered + 1 end
      if (t ~= false) ~= cov then
        assert(on_rim(x, y), string.format("%s: pixel (%d, %d): the ray %s the surface but the pixel is %s, away "
                                           .. "from the rim", name, x, y, t and "hits" or "misses",
                                           cov and "covered" or "uncovered"))
        n_rim = n_rim + 1
      elseif cov then
        local n = { rgba[1] * 2 - 1, rgba[2] * 2 - 1, rgba[3] * 2 - 1 }
        local cosang = dot(n, t) / math.sqrt(dot(n, n))
        local err = math.deg(math.acos(math.min(1, math.max(-1, cosang))))
        assert(err == err, string.format("%s: pixel (%d, %d) has a NaN normal", name, x, y))
        n_checked = n_checked + 1
        if err > max_err then max_err, worst = err, { x, y } end
      else
        assert(rgba[4] == 0, string.format("%s: background pixel (%d, %d) has alpha %g, not 0", name, x, y, rgba[4]))
      end
    end
  end
  print(string.format("%s: covered %d of %d pixels, %d rim disagreements, max normal error %.3f deg at (%d, %d)",
                      name, n_covered, W * H, n_rim, max_err, worst[1], worst[2]))
  assert(n_checked > 2000, name .. ": too few covered pixels to mean anything: " .. n_checked)
  assert(n_rim < 0.05 * n_covered, name .. ": too many rim disagreements: " .. n_rim)
  assert(max_err <= TOLERANCE_DEG, string.format("%s: max normal error %.3f deg at (%d, %d) exceeds %.1f deg", name,
                                                 max_err, worst[1], worst[2], TOLERANCE_DEG))
end

check("unit sphere", surface({ 0, 0, 0 }, { 1, 1, 1 }, 0))
check("rotated ellipsoid", surface({ 0.3, -0.2, 0.1 }, { 0.8, 0.5, 0.65 }, 30))

-- The smallest near the camera takes (far / 2^24) still covers what near = 0.5 does: below it a
-- sphere lost pixels (1e-7) or vanished (3e-8) without a word; now sn.camera refuses it.
local function covered(near)
  local view = sn.camera { eye = { 0, 0, 3 }, near = near, far = 10 }
  return sn.scene { mesh = sn.mesh.sphere {}, size = { 32, 32 }, views = { view } }:gbuffer {}:covered()
end
local want = covered(0.5)
assert(want > 400 and covered(10 / 2 ^ 24) == want, ("covered %d at near 0.5, %d at far / 2^24"):format(want, covered(10 / 2 ^ 24)))
local ok, err = pcall(sn.camera, { eye = { 0, 0, 3 }, near = 3e-8, far = 10 })
assert(not ok and err:find("near %(3e%-08%) is too small for far %(10%)"), err)

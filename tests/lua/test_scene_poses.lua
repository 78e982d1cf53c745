-- Scenes that cover directions: several view rings, meshes placed by transforms, poses of one
-- mesh. Each check below would fail if the option were ignored or applied wrongly.
local sn = require "shadenet"

local function normals_of(g)
  local img = g:read("normal")
  local w, h = img:size()
  local out = {}
  for y = 1, h do
    for x = 1, w do
      local p = img:get(x, y)
      if p[4] > 0.5 then out[#out + 1] = p end
    end
  end
  return out
end

-- 1. View rings: 3 rings of 4 at -30, 20 and 70 degrees make 12 cameras whose elevation above the
--    framed centre is the ring's.
local rings = sn.scene { mesh = "meshes/test_blob.glb", size = { 48, 48 },
                         views = { { count = 4, elevation = -30 }, { count = 4, elevation = 20 }, { count = 4, elevation = 70 } } }
local views = rings:views()
assert(#views == 12, "12 cameras, got " .. #views)
local lo, hi = rings:bounds()
local centre = { (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2, (lo[3] + hi[3]) / 2 }
for i, cam in ipairs(views) do
  local e = cam:eye()
  local d = { e[1] - centre[1], e[2] - centre[2], e[3] - centre[3] }
  local elevation = math.deg(math.asin(d[2] / math.sqrt(d[1] ^ 2 + d[2] ^ 2 + d[3] ^ 2)))
  local want = ({ -30, 20, 70 })[math.floor((i - 1) / 4) + 1]
  assert(math.abs(elevation - want) < 1e-6, ("camera %d at elevation %.4f, want %d"):format(i, elevation, want))
end
-- Cameras and rings mix in one list.
local mixed = sn.scene { mesh = "meshes/test_blob.glb", views = { views[1], { count = 2, elevation = 0 } } }
assert(#mixed:views() == 3)

-- 2. A transform turns a mesh: the plane faces +y; turned 90 degrees about x it faces +z, so every
--    covered pixel's normal is (0, 0, +-1) (back faces are flipped towards the eye).
local plane = sn.mesh.plane { size = 2 }
local turned = sn.scene { meshes = { { mesh = plane, transform = { rotate = { 90, 1, 0, 0 } } } }, size = { 32, 32 },
                          views = { { count = 4, elevation = 10 } } }
local seen = 0
for v = 1, 4 do
  for _, n in ipairs(normals_of(turned:gbuffer { view = v, attributes = { "normal" } })) do
    assert(math.abs(math.abs(n[3]) - 1) < 1e-4 and math.abs(n[2]) < 1e-3, ("normal %.4f %.4f %.4f"):format(n[1], n[2], n[3]))
    seen = seen + 1
  end
end
assert(seen > 100, "the turned plane is seen: " .. seen)

-- The same transform as 4 rows of a matrix (rotation about x by 90 degrees, about the plane's
-- centre, the origin) gives the same G-buffer.
local matrix = sn.scene { meshes = { { mesh = plane, transform = { { 1, 0, 0, 0 }, { 0, 0, -1, 0 }, { 0, 1, 0, 0 }, { 0, 0, 0, 1 } } } },
                          size = { 32, 32 }, views = { { count = 4, elevation = 10 } } }
local a, b = turned:gbuffer { view = 2 }:read("normal"), matrix:gbuffer { view = 2 }:read("normal")
assert(sn.image.mse(a, b, { channels = 4 }) < 1e-10, "matrix and terms agree")

-- Two meshes side by side: the scene's bounds hold both.
local pair = sn.scene { meshes = { { mesh = plane, transform = { translate = { -3, 0, 0 } } },
                                   { mesh = plane, transform = { translate = { 3, 0, 0 } } } } }
local plo, phi = pair:bounds()
assert(math.abs(plo[1] + 4) < 1e-6 and math.abs(phi[1] - 4) < 1e-6, ("bounds x %.3f..%.3f"):format(plo[1], phi[1]))

-- 3. Poses: the hanging cloth has no normal pointing further up than y = 0.40; tilted by +-60
--    degrees about x and z, its normals reach the pole and the dataset rows do too.
local function max_normal_y(data)
  local best = -1
  local tr, va = data:counts()
  for i = 1, tr do
    local x = data:row("train", i)
    best = math.max(best, x[2])
  end
  return best
end
local target = sn.lighting.phong {}
local one = sn.scene { mesh = "meshes/cloth.glb", size = { 64, 48 }, views = { count = 4, elevation = 20 } }
local five = sn.scene { mesh = "meshes/cloth.glb", size = { 64, 48 }, views = { count = 4, elevation = 20 },
                        poses = { {}, { rotate = { 60, 1, 0, 0 } }, { rotate = { -60, 1, 0, 0 } },
                                  { rotate = { 60, 0, 0, 1 } }, { rotate = { -60, 0, 0, 1 } } } }
assert(#five:poses() == 5 and tostring(five):find("4 views x 5 poses"), tostring(five))
local d1 = one:dataset { target = target, samples = "all" }
local covered1 = sn.dataset_stats().last_covered
local d5 = five:dataset { target = target, samples = "all" }
local covered5 = sn.dataset_stats().last_covered
assert(max_normal_y(d1) < 0.45, "one pose: max normal y " .. max_normal_y(d1))
assert(max_normal_y(d5) > 0.95, "five poses: max normal y " .. max_normal_y(d5))
assert(covered5 > covered1, ("five poses cover %d pixels, one %d"):format(covered5, covered1))
-- Pose 1 alone is the one-pose scene's data (the same framing cameras would differ, so compare
-- against a scene with the same views): poses = {1} is a subset with its own cache key.
local first = five:dataset { target = target, samples = "all", poses = { 1 } }
local t1, v1 = first:counts()
assert(t1 + v1 < covered5 and t1 + v1 > 0)
local g = five:gbuffer { view = 1, pose = 2, attributes = { "normal" } }
assert(#normals_of(g) > 0, "pose 2 is drawn")
local ok, err = pcall(five.gbuffer, five, { pose = 6 })
assert(not ok and err:find("pose.: 6 is outside the scene.s poses 1..5"), err)
ok, err = pcall(five.render, five, target, { pose = 3 })
assert(ok, err)
-- A view or pose listed twice would put the same rows in training and validation: refused, as
-- is an empty list (which selected every one).
ok, err = pcall(five.dataset, five, { target = target, views = { 1, 2, 1 } })
assert(not ok and err:find("option 'views': view 1 is listed twice", 1, true), err)
ok, err = pcall(five.dataset, five, { target = target, poses = { 3, 3 } })
assert(not ok and err:find("option 'poses': pose 3 is listed twice", 1, true), err)
ok, err = pcall(five.dataset, five, { target = target, views = {} })
assert(not ok and err:find("an empty list selects no view; leave it out for all 4 of them", 1, true), err)

-- 4. A transform that mirrors (a negative determinant) reverses the triangles' winding on screen:
--    a closed mesh seen from outside must still show its outward side (n . v > 0 everywhere; with
--    the winding taken as it was, every normal pointed inward), lit as the plain mesh is. As a
--    pose, as a mesh's transform and as a matrix.
local sphere = sn.mesh.sphere {}
local light = { dir = { 0, 1, 0 } }
local plain = sn.scene { mesh = sphere, size = { 48, 48 }, views = { count = 1, elevation = 0 }, light = light }
local mirrors = {
  pose = sn.scene { mesh = sphere, size = { 48, 48 }, views = { count = 1, elevation = 0 }, light = light,
                    poses = { { scale = { -1, 1, 1 } } } },
  transform = sn.scene { meshes = { { mesh = sphere, transform = { rotate = { 30, 0, 1, 0 }, scale = { 1, 1, -1 } } } },
                         size = { 48, 48 }, views = { count = 1, elevation = 0 }, light = light },
  matrix = sn.scene { mesh = sphere, size = { 48, 48 }, views = { count = 1, elevation = 0 }, light = light,
                      poses = { { { -1, 0, 0, 0 }, { 0, -1, 0, 0 }, { 0, 0, -1, 0 }, { 0, 0, 0, 1 } } } },
}
local flat = sn.lighting.phong { specular = 0 }
local truth = plain:render(flat)
for how, s in pairs(mirrors) do
  local gb = s:gbuffer { attributes = { "normal", "view" } }
  local n, v = gb:read("normal"), gb:read("view")
  local w, h = n:size()
  local covered = 0
  for y = 1, h do
    for x = 1, w do
      local a, b = n:get(x, y), v:get(x, y)
      if a[4] > 0.5 then
        covered = covered + 1
        local d = a[1] * b[1] + a[2] * b[2] + a[3] * b[3]
        assert(d > -1e-3, ("mirrored by a %s: pixel %d,%d has n.v = %.3f (the inward side)"):format(how, x, y, d))
      end
    end
  end
  assert(covered > 300, how .. ": covered " .. covered)
  -- The sphere is symmetric, so the mirrored one looks the same up to its triangles' seams.
  local e = sn.image.mse(s:render(flat), truth)
  assert(e < 1e-3, ("mirrored by a %s: MSE %.3g against the plain sphere"):format(how, e))
end

print("scene views, transforms and poses: ok")

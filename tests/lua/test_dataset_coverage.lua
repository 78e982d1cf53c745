-- ds:coverage on real data: the hanging cloth's normals never point far up or down, so a
-- sphere's pixels fall largely outside its bins, while a sphere's own rows cover the sphere.
local sn = require "shadenet"

local size, views = { 320, 240 }, { count = 8, elevation = 20 }
local phong = sn.lighting.phong {}
local cloth = sn.scene { mesh = "meshes/cloth.glb", size = size, views = views }
local sphere = sn.scene { mesh = sn.mesh.sphere {}, size = size, views = views }
local data = cloth:dataset { inputs = { "normal", "view" }, target = phong, samples = "all" }

local t0 = os.clock()
local c = data:coverage()
local seconds = os.clock() - t0
local train, val = data:counts()
assert(c.rows == train + val, "both sets count: " .. c.rows)
assert(c.normal.bins == 512 and c.view.bins == 256 and c.min_count == 1)
assert(c.invalid == 0 and c.non_unit == 0, c.invalid .. " invalid, " .. c.non_unit .. " non-unit")
-- No cloth normal points further up than y = 0.40 (or down below -0.40): at most the middle
-- 7 of 16 bands (y in [-0.5, 0.375) holds 7 bands; 0.40 reaches into the 8th).
assert(c.normal.y_max < 0.42 and c.normal.y_min > -0.42, ("normal y %.3f..%.3f"):format(c.normal.y_min, c.normal.y_max))
assert(c.normal.fraction > 0.25 and c.normal.fraction <= 8 / 16, "cloth normal coverage " .. c.normal.fraction)
assert(c.view.fraction > 0.3 and c.view.fraction < 0.7, "cloth view coverage " .. c.view.fraction)
assert(c.normal.covered == math.floor(c.normal.fraction * 512 + 0.5))
assert(c.scheme:match("^normal: 16 bands uniform in y = cos%(theta%) x 32 sectors"), c.scheme)

-- Against the sphere's pixels: more than half of them have a normal the cloth never had.
local figure = "out/tests/coverage_cloth_vs_sphere.png"
os.remove(figure)
local r = data:coverage { against = sphere, figure = figure, title = "cloth against a sphere" }
assert(r.figure == figure)
assert(r.against_rows > 50000, "sphere pixels " .. r.against_rows)
assert(r.outside.normal > 0.45 and r.outside.normal < 0.65, "sphere normals outside the cloth's: " .. r.outside.normal)
assert(r.outside.view > 0.15 and r.outside.view < 0.4, "sphere views outside: " .. r.outside.view)
assert(r.outside.either >= r.outside.normal and r.outside.either >= r.outside.view)
assert(r.outside.either <= r.outside.normal + r.outside.view + 1e-12)
local img = sn.image.load(figure)
local w, h = img:size()
assert(w == 1454 and h == 420, "figure is " .. w .. "x" .. h)
-- The red of "only the sphere has rows here" is in it.
local red = 0
for y = 1, h, 4 do
  for x = 1, w, 4 do
    local p = img:get(x, y)
    if p[1] > 0.85 and p[2] < 0.15 and p[3] < 0.15 then red = red + 1 end
  end
end
assert(red > 2000, "red samples: " .. red)

-- The sphere's own rows (every covered pixel) against its own pixels: nothing outside.
local own = sphere:dataset { inputs = { "normal", "view" }, target = phong, samples = "all" }
local s = own:coverage { against = sphere }
assert(s.against_rows == s.rows, s.against_rows .. " vs " .. s.rows)
assert(s.outside.normal == 0 and s.outside.view == 0 and s.outside.either == 0,
       ("own outside %g %g %g"):format(s.outside.normal, s.outside.view, s.outside.either))
assert(s.normal.fraction > 0.85, "sphere normal coverage " .. s.normal.fraction)
-- ... and the cloth, seen against the sphere's rows, is mostly inside them.
local back = own:coverage { against = data }
assert(back.outside.normal < 0.01, "cloth normals outside the sphere's: " .. back.outside.normal)

-- min_count: fewer bins hold 50 rows than hold one.
local strict = data:coverage { min_count = 50 }
assert(strict.normal.covered < c.normal.covered and strict.min_count == 50)
-- Coarser bins: 4 bands x 4 sectors (the middle two bands hold the cloth's normals).
local coarse = data:coverage { normal_bands = 4, normal_sectors = 4, view_bands = 2, view_sectors = 4 }
assert(coarse.normal.bins == 16 and coarse.normal.covered == 8, "coarse covered " .. coarse.normal.covered)

print(("cloth %dx%d, %d rows: normal %.3f, view %.3f covered; sphere outside: normal %.3f view %.3f either %.3f; %.1f ms")
  :format(size[1], size[2], c.rows, c.normal.fraction, c.view.fraction, r.outside.normal, r.outside.view,
          r.outside.either, seconds * 1000))

-- Networks conditioned on material parameters: a dataset that varies a parameter per row (its
-- targets are the model at that row's value), a network that takes it as an input and renders
-- any value in its range as a uniform (checked against net:forward on the same inputs), and a
-- checkpoint that keeps the condition and its range.
local sn = require "shadenet"

local fails = require("expect").fails

local scene = sn.scene { mesh = sn.mesh.sphere {}, size = { 64, 64 }, views = { { count = 3, elevation = -20 },
                                                                                 { count = 3, elevation = 40 } } }
local gold = sn.lighting.ggx {}
local inputs = { "normal", "view", "roughness" }
local data = scene:dataset { target = gold, vary = { roughness = { 0.1, 0.8 } }, inputs = inputs, samples = 4000 }
assert(data:inputs() == 7 and table.concat(data:input_names(), ",") == "normal,view,roughness", "7 inputs")

-- Each row's target is the model at the row's own roughness (the twin at it), and the
-- roughnesses spread over the range.
local lo, hi, worst = 1, 0, 0
for i = 1, 200 do
  local x, y = data:row("train", i)
  lo, hi = math.min(lo, x[7]), math.max(hi, x[7])
  local t = gold:with { roughness = x[7] }:shade { normal = { x[1], x[2], x[3] }, view = { x[4], x[5], x[6] } }
  for c = 1, 3 do worst = math.max(worst, math.abs(t[c] - y[c])) end
end
assert(worst < 2e-5, "targets vs the twin at each row's roughness: " .. worst)
assert(lo >= 0.1 and hi <= 0.8 and lo < 0.15 and hi > 0.75, ("roughness spread %.3f..%.3f"):format(lo, hi))

-- Coverage finds normal and view beside the varied parameter (it refused every conditioned
-- dataset), and counts what the same rows without it count.
local cov = data:coverage {}
local x, y = {}, {}
for _, set in ipairs { "train", "val" } do
  for i = 1, select(set == "train" and 1 or 2, data:counts()) do
    local r = data:row(set, i)
    x[#x + 1], y[#y + 1] = { r[1], r[2], r[3], r[4], r[5], r[6] }, { 0, 0, 0 }
  end
end
local plain = sn.dataset { x = x, y = y, input_names = { "normal", "view" } }:coverage {}
assert(cov.rows == 4000 and cov.invalid == 0 and cov.non_unit == 0, ("coverage rows %d, invalid %d, non-unit %d"):format(
  cov.rows, cov.invalid, cov.non_unit))
assert(cov.normal.covered == plain.normal.covered and cov.view.covered == plain.view.covered, "the same bins as without it")
-- Its CSV export is refused (the reader could not read back the file it wrote); .json keeps it.
fails(function() data:export("never_written.csv") end, "CSV column names cannot carry the varied parameter 'roughness'")

-- Deterministic per seed; the range is part of the cache key.
sn.dataset_cache_clear()
local builds = sn.dataset_stats().builds
local a = scene:dataset { target = gold, vary = { roughness = { 0.1, 0.8 } }, inputs = inputs, samples = 4000 }
local b = scene:dataset { target = gold, vary = { roughness = { 0.1, 0.5 } }, inputs = inputs, samples = 4000 }
local xa, xb = a:row("train", 1), b:row("train", 1)
assert(xa[7] ~= xb[7] and xb[7] <= 0.5, "a different range gives different rows")
assert(sn.dataset_stats().builds == builds + 2, "two ranges, two builds")
sn.dataset_cache_clear()
local c = scene:dataset { target = gold, vary = { roughness = { 0.1, 0.8 } }, inputs = inputs, samples = 4000, seed = 1 }
assert(sn.dataset_stats().builds == builds + 3, "built again, not cached")
for i = 1, 50 do
  local p, q = a:row("train", i), c:row("train", i)
  for k = 1, 7 do assert(p[k] == q[k], "same seed, same rows") end
end

-- Bad requests.
fails(function() scene:dataset { target = gold, vary = { roughness = { 0.1, 0.8 } } } end,
      "vary 'roughness': list it among the inputs too")
fails(function() scene:dataset { target = gold, vary = { f0 = { 0, 1 } }, inputs = { "normal", "view", "f0" } } end,
      "parameter 'f0' has 3 components; only numbers can vary per row")
fails(function() scene:dataset { target = gold, vary = { roughness = { 0.5, 1.5 } }, inputs = inputs } end,
      "must be ordered and inside the parameter's domain [0, 1]")
fails(function() scene:dataset { target = gold, vary = { shine = { 0, 1 } }, inputs = { "normal", "view", "shine" } } end,
      "has no parameter 'shine' to vary (valid: roughness, f0, diffuse, ambient)")

-- A conditioned network: its condition and range come from the dataset.
local net = sn.mlp { inputs = 7, hidden = { 12, 12, 12 }, outputs = 3, seed = 2 }
sn.train { nets = { net }, data = data, epochs = 3, batch = 8 }
local conds = net:conditions()
assert(#conds == 1 and conds[1].name == "roughness" and conds[1].min == 0.1 and conds[1].max == 0.8, "condition")
assert(math.abs(conds[1].value - 0.45) < 1e-12, "renders at the middle of the range until set")

-- The render passes the value as a uniform: each covered pixel equals net:forward on the
-- G-buffer's normal and view with that roughness.
local g = scene:gbuffer { view = 2, attributes = { "normal", "view" } }
local nimg, vimg = g:read("normal"), g:read("view")
local function check_render(img, r)
  local checked, err = 0, 0
  for y = 8, 56, 6 do
    for x = 8, 56, 6 do
      local n = nimg:get(x, y)
      if n[4] > 0.5 then
        local v = vimg:get(x, y)
        local f = net:forward { n[1], n[2], n[3], v[1], v[2], v[3], r }
        local p = img:get(x, y)
        for k = 1, 3 do err = math.max(err, math.abs(p[k] - f[k])) end
        checked = checked + 1
      end
    end
  end
  assert(checked > 20 and err < 1e-4, ("render vs forward at roughness %g: %g over %d pixels"):format(r, err, checked))
end
local at2 = net:render(g, { values = { roughness = 0.2 } })
check_render(at2, 0.2)
net:set_input("roughness", 0.7)
local at7 = net:render(g)
check_render(at7, 0.7)
assert(sn.image.mse(at2, at7, { channels = 3 }) > 1e-6, "the value changes the image")
local via_scene = scene:render(net, { view = 2, values = { roughness = 0.2 } })
assert(sn.image.mse(via_scene, at2) == 0, "scene:render takes the same values")
fails(function() net:render(g, { values = { roughness = 0.9 } }) end, "outside the range the network was trained on, [0.1, 0.8]")
fails(function() net:set_input("gloss", 0.3) end, "'gloss' is not a condition input")
fails(function() scene:render(gold, { values = { roughness = 0.2 } }) end, "for a lighting model use model:with")

-- The checkpoint keeps the condition, its range and its value.
sn.fs.mkdir("out")
net:save("out/conditioned.snmlp")
local back = sn.load("out/conditioned.snmlp")
local bc = back:conditions()
assert(#bc == 1 and bc[1].name == "roughness" and bc[1].min == 0.1 and bc[1].max == 0.8 and bc[1].value == 0.7,
       "loaded condition")
assert(sn.image.mse(back:render(g), at7) == 0, "the loaded network renders the same")
os.remove("out/conditioned.snmlp")

-- Trained again on another range, the conditions follow it (they kept the first range, and
-- values the network was last trained on were refused): a value still inside stays, one outside
-- goes to the middle.
net:set_input("roughness", 0.3)
sn.train { nets = { net }, data = scene:dataset { target = gold, vary = { roughness = { 0.1, 0.5 } }, inputs = inputs, samples = 400 },
           epochs = 1, batch = 8 }
local nc = net:conditions()[1]
assert(nc.min == 0.1 and nc.max == 0.5 and nc.value == 0.3, ("retrained: [%g, %g] at %g"):format(nc.min, nc.max, nc.value))
sn.train { nets = { net }, data = scene:dataset { target = gold, vary = { roughness = { 0.4, 0.9 } }, inputs = inputs, samples = 400 },
           epochs = 1, batch = 8 }
nc = net:conditions()[1]
assert(nc.min == 0.4 and nc.max == 0.9 and math.abs(nc.value - 0.65) < 1e-12, ("[%g, %g] at %g"):format(nc.min, nc.max, nc.value))
net:set_input("roughness", 0.85)
-- Just outside: the message shows the digits that make it so, not a value that reads as the bound.
fails(function() net:set_input("roughness", 0.9000001) end, "'roughness' = 0.9000001 lies outside the range the network was trained on, [0.4, 0.9]")
print("ok")

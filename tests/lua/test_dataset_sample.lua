-- sn.dataset.sample{...}: rows drawn from the lighting model's domain, as scripts see them: the
-- domains hold, the targets are the model's (the CPU twin, model:shade), the same request is a
-- cache hit that renders nothing, a network trains on it, and bad options are refused by name.
local sn = require "shadenet"

local ggx = sn.lighting.ggx { roughness = 0.3, f0 = { 1.0, 0.71, 0.29 } }
local light = { dir = { 0.5, 0.7, 0.6 }, color = { 1, 0.9, 0.8 } }

local function dot(a, b) return a[1] * b[1] + a[2] * b[2] + a[3] * b[3] end
local function len(a) return math.sqrt(dot(a, a)) end

-- Every row of both sets, as (normal, view, target).
local function rows(ds)
  local out = {}
  local train, val = ds:counts()
  for _, set in ipairs { { "train", train }, { "val", val } } do
    for i = 1, set[2] do
      local x, y = ds:row(set[1], i)
      out[#out + 1] = { n = { x[1], x[2], x[3] }, v = { x[4], x[5], x[6] }, y = y }
    end
  end
  return out
end

sn.dataset_cache_clear()
local s0 = sn.dataset_stats()
local data = sn.dataset.sample { target = ggx, n = 2000, normals = "hemisphere", views = "cosine",
                                 light = light, seed = 3 }
assert(tostring(data) == "Dataset(6 -> 3 rgb, 1600 train / 400 val)", tostring(data))
local names = data:input_names()
assert(#names == 2 and names[1] == "normal" and names[2] == "view", "input names")
local s1 = sn.dataset_stats()
assert(s1.builds == s0.builds + 1 and s1.gbuffer_renders == s0.gbuffer_renders, "one build, no render")

-- Domains and targets, row by row.
local all = rows(data)
assert(#all == 2000)
local worst, mean_nv = 0, 0
for i, r in ipairs(all) do
  assert(math.abs(len(r.n) - 1) < 1e-6 and math.abs(len(r.v) - 1) < 1e-6, "row " .. i .. " not unit")
  assert(r.n[2] >= 0, "row " .. i .. ": hemisphere normal below y = 0")
  local nv = dot(r.n, r.v)
  assert(nv > 0, "row " .. i .. ": the view faces away")
  mean_nv = mean_nv + nv / #all
  local twin = ggx:shade { normal = r.n, view = r.v, light = light }
  for c = 1, 3 do worst = math.max(worst, math.abs(r.y[c] - twin[c])) end
end
-- 1e-5: the GPU's float against the double twin (tests/unit/test_lighting_twin.cpp's bound);
-- a row within 1e-4 of n.l = 0 may differ more, and none of these 2000 is.
assert(worst < 1e-5, "targets differ from the twin by " .. worst)
assert(math.abs(mean_nv - 2 / 3) < 1e-3, "cosine views: mean n.v " .. mean_nv .. ", expected 2/3")

-- The same request: a hit, the same object's rows; a fresh build after clearing: the same rows.
local again = sn.dataset.sample { target = ggx, n = 2000, normals = "hemisphere", views = "cosine",
                                  light = light, seed = 3 }
local s2 = sn.dataset_stats()
assert(s2.hits == s1.hits + 1 and s2.builds == s1.builds, "identical request must hit")
sn.dataset_cache_clear()
local rebuilt = sn.dataset.sample { target = ggx, n = 2000, normals = "hemisphere", views = "cosine",
                                    light = light, seed = 3 }
assert(sn.dataset_stats().builds == s2.builds + 1, "cleared cache must build")
local a, b = again:row("val", 17), rebuilt:row("val", 17)
for c = 1, 6 do assert(a[c] == b[c], "same seed, other rows") end
local other = sn.dataset.sample { target = ggx, n = 2000, normals = "hemisphere", views = "cosine",
                                  light = light, seed = 4 }
assert(other:row("val", 17)[1] ~= a[1], "another seed must draw other rows")

-- Uniform views around sphere normals: mean n.v 1/2; the colour space is the one asked for.
local hsv = sn.dataset.sample { target = sn.lighting.phong {}, n = 1000, color = "hsv" }
assert(hsv:color() == "hsv")
local m = 0
for _, r in ipairs(rows(hsv)) do m = m + dot(r.n, r.v) / 1000 end
assert(math.abs(m - 0.5) < 1e-3, "uniform views: mean n.v " .. m)

-- "lit": every normal faces the light.
local lit = sn.dataset.sample { target = ggx, n = 500, normals = "lit", light = { dir = { -1, 0.2, 0.1 } } }
local l = { -1, 0.2, 0.1 }
for i, r in ipairs(rows(lit)) do assert(dot(r.n, l) >= -1e-6, "lit row " .. i .. " faces away from the light") end

-- A tilted hemisphere.
local tilted = sn.dataset.sample { target = ggx, n = 500, normals = "hemisphere", axis = { 0, 0, -2 } }
for i, r in ipairs(rows(tilted)) do assert(r.n[3] <= 1e-6, "tilted row " .. i) end

-- A network trains on it.
local net = sn.mlp { inputs = 6, hidden = { 8 }, outputs = 3, seed = 1 }
local run = sn.train { nets = { net }, data = data, epochs = 2, backend = "cpu", seed = 1 }
assert(run[1].best_val_mse > 0 and run[1].best_val_mse < 1, "trained on sampled rows")

-- Refusals, each naming what is wrong.
local function refuses(options, pattern)
  local ok, err = pcall(sn.dataset.sample, options)
  assert(not ok, "accepted: " .. pattern)
  assert(tostring(err):find(pattern, 1, true), "message '" .. tostring(err) .. "' lacks '" .. pattern .. "'")
end
local builds = sn.dataset_stats().builds
refuses({ n = 100 }, "sn.dataset.sample option 'target' is required")
refuses({ target = "ggx" }, "option 'target': a lighting model (sn.lighting.*{...}) expected, got the string 'ggx' "
                            .. "(sn.lighting.ggx {} makes that model")
refuses({ target = 3 }, "option 'target': a lighting model (sn.lighting.*{...}) expected, got number")
refuses({ target = ggx, normals = "cube" }, "unknown normals domain 'cube' (valid: sphere, hemisphere, lit)")
refuses({ target = ggx, views = "sphere" }, "unknown views domain 'sphere' (valid: uniform, cosine)")
refuses({ target = ggx, n = 1 }, "option 'n' must be a whole number in 2..16777216")
refuses({ target = ggx, n = 100.5 }, "got 100.5")
refuses({ target = ggx, n = 2 ^ 24 + 1 }, "got 16777217")
refuses({ target = ggx, n = math.huge }, "got inf")
refuses({ target = ggx, n = 0 / 0 }, "option 'n' must be a whole number")
refuses({ target = ggx, n = "many" }, "option 'n': number expected, got string")
refuses({ target = ggx, split = 1 }, "split must lie strictly between 0 and 1")
refuses({ target = ggx, split = 0 }, "split must lie strictly between 0 and 1")
refuses({ target = ggx, normals = "hemisphere", axis = { 0, 0, 0 } }, "option 'axis' must be a non-zero, finite direction")
refuses({ target = ggx, axis = { 0, 0, 1 } }, "option 'axis' is for normals = \"hemisphere\" only")
refuses({ target = ggx, seed = -1 }, "option 'seed' must be a whole number")
refuses({ target = ggx, samples = 10 }, "unknown option 'samples'")
refuses({ target = sn.lighting.textured_phong {} }, "textured_phong")
refuses({ target = ggx, light = { dir = { 0, 0, 0 } } }, "light 'dir' must be a non-zero")
assert(sn.dataset_stats().builds == builds, "a refused request builds nothing")
-- Two rows split one of each (it was an error, though n's range starts at 2).
assert(select(2, sn.dataset.sample { target = ggx, n = 2, split = 0.9 }:counts()) == 1, "2 rows: one of each")
print("ok")

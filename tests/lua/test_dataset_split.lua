-- scene:dataset: the thesis' scale and 4:1 split by default, deterministic per seed, different
-- per seed; inputs in the order asked; targets equal to the twin of their inputs.
local sn = require "shadenet"

-- The defaults: 256 x 256 images from 8 views framing the mesh.
local scene = sn.scene { mesh = "meshes/cloth.glb" }
assert(#scene:views() == 8 and select(1, scene:size()) == 256, tostring(scene))
local phong = sn.lighting.phong {}

-- Default: 64,149 samples (the thesis' count), 80/20.
local d = scene:dataset { target = phong }
local train, val = d:counts()
assert(train + val == 64149, "default samples: " .. (train + val))
assert(train == 51319 and val == 12830, string.format("4:1 split: %d / %d", train, val))
assert(sn.dataset_stats().last_covered > 64149, "the default views cover more than 64,149 pixels")
assert(d:inputs() == 6 and d:outputs() == 3 and d:color() == "rgb", tostring(d))
assert(d:input_names()[1] == "normal" and d:input_names()[2] == "view", "input names")

-- Targets are the twin of the inputs (normal, view) under the scene's light.
local light = scene:light()
for i = 1, 200, 13 do
  local x, y = d:row("train", i)
  local t = phong:shade { normal = { x[1], x[2], x[3] }, view = { x[4], x[5], x[6] }, light = light }
  for c = 1, 3 do
    assert(math.abs(y[c] - t[c]) < 1e-5, string.format("row %d channel %d: %.7f vs twin %.7f", i, c, y[c], t[c]))
  end
end

-- Determinism: a second build (cache cleared) gives the same rows; another seed does not.
local function rows(ds, set, n)
  local out = {}
  for i = 1, n do
    local x, y = ds:row(set, i)
    out[#out + 1] = table.concat(x, ",") .. "|" .. table.concat(y, ",")
  end
  return table.concat(out, "\n")
end
local a = scene:dataset { target = phong, seed = 11, samples = 3000 }
sn.dataset_cache_clear()
local b = scene:dataset { target = phong, seed = 11, samples = 3000 }
assert(rows(a, "train", 50) == rows(b, "train", 50), "same seed, same training rows")
assert(rows(a, "val", 50) == rows(b, "val", 50), "same seed, same validation rows")
local c = scene:dataset { target = phong, seed = 12, samples = 3000 }
assert(rows(a, "train", 50) ~= rows(c, "train", 50), "another seed, another split")
local t2, v2 = c:counts()
assert(t2 == 2400 and v2 == 600, "3000 samples split 4:1")

-- samples = "all": every covered pixel.
local all = scene:dataset { target = phong, samples = "all", split = 0.5 }
local ta, va = all:counts()
assert(ta + va == sn.dataset_stats().last_covered, "all covered pixels")

-- Position + uv inputs (the thesis' texture experiments): 5 inputs in the order asked.
local tex = scene:dataset { inputs = { "uv", "position" }, target = sn.lighting.textured_phong {}, samples = 2000 }
assert(tex:inputs() == 5, "uv (2) + position (3)")
local x = tex:row("train", 1)
assert(x[1] >= 0 and x[1] <= 1 and x[2] >= 0 and x[2] <= 1, "uv first")
print("ok")

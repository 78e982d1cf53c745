-- Datasets are cached by content: an identical request renders nothing (sn.dataset_stats()
-- counts G-buffer renders and builds); a change to any part of the key builds anew.
local sn = require "shadenet"

local function scene_of(o)
  return sn.scene { mesh = o.mesh or "meshes/test_blob.glb", size = o.size or { 48, 40 },
                    views = o.views or { count = 2, elevation = 20 }, light = o.light }
end

local scene = scene_of {}
local phong = sn.lighting.phong {}
local base = { inputs = { "normal", "view" }, target = phong, seed = 1, samples = 500 }
local function request(changes)
  local r = {}
  for k, v in pairs(base) do r[k] = v end
  for k, v in pairs(changes or {}) do r[k] = v end
  return r
end

local first = scene:dataset(request())
local s0 = sn.dataset_stats()
local again = scene:dataset(request())
local s1 = sn.dataset_stats()
assert(s1.builds == s0.builds, "an identical request must not build")
assert(s1.gbuffer_renders == s0.gbuffer_renders, "an identical request must not render")
assert(s1.hits == s0.hits + 1, "an identical request is a cache hit")
local x1, y1 = first:row("train", 7)
local x2, y2 = again:row("train", 7)
assert(x1[4] == x2[4] and y1[2] == y2[2], "the cached dataset is the same data")

-- A fresh scene object with the same content hits too: the key is content, not identity.
scene_of {}:dataset(request())
assert(sn.dataset_stats().builds == s1.builds, "same content, new scene object: no build")

-- Every part of the key: each change must build once, and asking again must hit.
local changes = {
  { "model parameter", scene, request { target = sn.lighting.phong { shininess = 33 } } },
  { "model", scene, request { target = sn.lighting.blinn_phong {} } },
  { "inputs", scene, request { inputs = { "normal", "view", "position" } } },
  { "input order", scene, request { inputs = { "view", "normal" } } },
  { "colour space", scene, request { color = "hsv" } },
  { "split", scene, request { split = 0.75 } },
  { "seed", scene, request { seed = 2 } },
  { "samples", scene, request { samples = 400 } },
  { "views subset", scene, request { views = { 2 } } },
  { "image size", scene_of { size = { 48, 41 } }, request() },
  { "cameras", scene_of { views = { count = 2, elevation = 21 } }, request() },
  { "light", scene_of { light = { dir = { 0.5, 0.7, 0.61 } } }, request() },
  { "light colour", scene_of { light = { color = { 1, 1, 0.9 } } }, request() },
  { "mesh", scene_of { mesh = "meshes/cloth.glb" }, request() },
  { "mesh content", scene_of { mesh = sn.mesh.load("meshes/test_blob.glb"):transformed { scale = 1.001 } }, request() },
}
for _, c in ipairs(changes) do
  local label, sc, req = c[1], c[2], c[3]
  local before = sn.dataset_stats()
  local d = sc:dataset(req)
  local mid = sn.dataset_stats()
  assert(mid.builds == before.builds + 1, label .. ": a changed key must build a new dataset")
  assert(mid.gbuffer_renders > before.gbuffer_renders, label .. ": a build renders")
  sc:dataset(req)
  local after = sn.dataset_stats()
  assert(after.builds == mid.builds and after.hits == mid.hits + 1, label .. ": asking again must hit")
  assert(d:counts() > 0, label .. ": empty dataset")
end

-- scene:set_light changes the key of the same scene object.
local before = sn.dataset_stats().builds
scene:set_light { dir = { -0.5, 0.7, 0.6 } }
scene:dataset(request())
assert(sn.dataset_stats().builds == before + 1, "set_light must invalidate")
print("ok")

-- The live reload test's scene: a small Phong network trained once through sn.keep (it prints
-- TRAINED when it does) and shown with its ground truth through scene:render, the path
-- examples/live_edit.lua takes. The test rewrites a copy of this file.
local sn = require "shadenet"

local scene = sn.scene { mesh = sn.mesh.sphere { segments = 32, rings = 16 }, size = { 64, 64 },
                         views = { count = 2, elevation = 20 }, light = { dir = { 0.3, 0.5, 0.8 } } }
local phong = sn.lighting.phong {}
local net = sn.keep("net", function()
  local data = scene:dataset { inputs = { "normal", "view" }, target = phong, split = 0.8, seed = 1 }
  local n = sn.mlp { inputs = 6, hidden = { 8, 8 }, outputs = 3, seed = 2 }
  sn.train { nets = n, data = data, epochs = 3, batch = 8, backend = "cpu", adam = { lr = 3e-3 } }
  print("TRAINED " .. n:trained_steps())
  return n
end)
-- EDITS

sn.live.show { scene = scene, network = net, truth = phong, title = "live test" }

-- Live weight editing, as in the thesis' section 4.4: a network of 8 hidden layers of 12
-- neurons is fitted once to the three-colour toon shading (Fig. 4.13) of a bumpy sphere, then edited by hand.
--
--   build/shadenet --window --watch examples/live_edit.lua
--
-- trains it once (sn.keep), opens a window on the mesh and watches this file: uncomment or
-- change an edit below, save, and the next frame shows it. Deleting an edit undoes it. Keys:
-- 1 network, 2 truth, 3 |error|, 4 side by side; drag to orbit, right-drag to move the light.
-- Run plainly (build/shadenet examples/live_edit.lua) it saves the four views to out/live_edit/.
local sn = require "shadenet"

local scene = sn.scene { mesh = "meshes/test_blob.glb", size = { 320, 320 }, views = { count = 8, elevation = 20 },
                         light = { dir = { 0.3, 0.5, 0.8 } } }
local toon = sn.lighting.toon3 {}  -- ambient, diffuse and specular colours over four Phong thresholds

local net = sn.keep("toon 8x12", function()
  local data = scene:dataset { inputs = { "normal", "view" }, target = toon, split = 0.8, seed = 1 }
  local net = sn.mlp { inputs = 6, hidden = { 12, 12, 12, 12, 12, 12, 12, 12 }, outputs = 3, seed = 1 }
  local run = sn.train { nets = net, data = data, epochs = 20, batch = 8, keep = "best",
                         adam = { lr = 2.5e-4, beta1 = 0.8, beta2 = 0.9 } }  -- the thesis' settings
  print(("trained %s once: best val MSE %.3g at epoch %d"):format(tostring(net), run[1].best_val_mse,
                                                                   run[1].best_epoch))
  return net
end)

-- EDITS: each line sets one parameter of the trained network (layer 1 = first hidden layer,
-- layer 9 = the output layer; weight[row][column] = [to neuron][from input]).
-- What each did here (seed 1, cpu backend) is in docs/live-mode.md; try your own.
local L = net.layers
-- L[1].weight[2][1] = 2.0               -- first hidden layer: the highlight moves left (Fig. 4.14)
-- L[9].bias[2] = L[9].bias[2] + 0.3     -- output layer: every colour turns yellow-green (Fig. 4.15)
-- L[6].bias[4] = -1.5                   -- a middle layer: lit side pink, highlight pale green (Fig. 4.16)

sn.live.show { scene = scene, network = net, truth = toon, title = "toon3, 8 x 12" }

if not sn.live.active() then  -- a plain run: the views as files
  sn.fs.mkdir("out/live_edit")
  for _, mode in ipairs({ "network", "truth", "error", "side" }) do
    local path = "out/live_edit/" .. mode .. ".png"
    sn.live.render { mode = mode, width = 480, height = 480 }:read():save(path)
    print("saved " .. path)
  end
end

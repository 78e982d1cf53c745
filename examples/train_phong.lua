-- Trains a 4 x 6 network (4 hidden layers of 6 tanh units) to shade like Phong on the cloth,
-- then writes the model, the network and their difference as three images.
--   build/shadenet examples/train_phong.lua [OUT_DIR]     (default out/train_phong)
local sn = require "shadenet"

local out = arg and arg[1] or "out/train_phong"
local scene = sn.scene { mesh = "meshes/cloth.glb", size = { 480, 360 }, views = { count = 8, elevation = 20 } }
local phong = sn.lighting.phong {}

-- world normal + view direction (6 numbers) -> RGB, at ~64k covered pixels split 4:1
local data = scene:dataset { inputs = { "normal", "view" }, target = phong, seed = 1 }
local net = sn.mlp { inputs = 6, hidden = { 6, 6, 6, 6 }, outputs = 3, activation = "tanh", seed = 1 }
local r = sn.train { nets = { net }, data = data, epochs = 20, batch = 8,
                     adam = { lr = 0.00025, beta1 = 0.8, beta2 = 0.9 }, seed = 1, keep = "best" }
print(string.format("%s: best validation MSE %.3g at epoch %d (%.1f s, %s backend)", tostring(net),
                    r[1].best_val_mse, r[1].best_epoch, r[1].wall_time, r[1].backend))

local truth = scene:render(phong, { view = 2 })
local mine = scene:render(net, { view = 2 })
local heat = sn.image.heatmap(sn.image.diff(truth, mine), { mask = truth, label = "|error|" })
sn.fs.mkdir(out)
for name, img in pairs { truth = truth, network = mine, error = heat } do
  print("wrote " .. img:save(out .. "/" .. name .. ".png"))
end
print(string.format("image MSE over covered pixels: %.3g", sn.image.mse(truth, mine, { channels = 3, mask = truth })))

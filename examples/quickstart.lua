-- shadenet's first job: teach two tiny networks to shade like the Phong and the GGX lighting
-- models, then compare them with the models on the mesh they learned from and on one they never
-- saw. Run from the repository root:
--   build/shadenet examples/quickstart.lua [OUT_DIR]      (default results/quickstart)
-- It writes OUT_DIR/quickstart.png (truth | network | error, per model and mesh) and
-- OUT_DIR/table.md, and prints where they are. About a minute on a 2-core machine without a GPU.
local sn = require "shadenet"

local out = arg and arg[1] or "results/quickstart"
local t_start = sn.clock()

-- 1. Scenes: the cloth the networks learn from (8 views around it, like the thesis' 64,149
--    covered pixels), and a different mesh to test them on.
local cloth = sn.scene { mesh = "meshes/cloth.glb", size = { 640, 480 }, views = { count = 8, elevation = 20 } }
local blob = sn.scene { mesh = "meshes/test_blob.glb", size = { 480, 360 }, views = { count = 8, elevation = 20 } }
local small_cloth = sn.scene { mesh = "meshes/cloth.glb", size = { 480, 360 }, views = { count = 8, elevation = 20 } }

-- 2. What to learn: two lighting models, and the network the thesis recommends for each
--    (Phong: 4 hidden layers of 6; GGX: about 10 neurons and 6-8 layers).
local cases = {
  { name = "Phong", model = sn.lighting.phong {}, hidden = { 6, 6, 6, 6 } },
  { name = "GGX", model = sn.lighting.ggx {}, hidden = { 10, 10, 10, 10, 10, 10, 10, 10 } },
}

local panels, rows = {}, {}
for _, c in ipairs(cases) do
  -- 3. A dataset: world normal + view direction -> the model's RGB at every covered pixel,
  --    split 4:1 into training and validation rows.
  local data = cloth:dataset { inputs = { "normal", "view" }, target = c.model, seed = 1 }
  local net = sn.mlp { inputs = 6, hidden = c.hidden, outputs = 3, activation = "tanh", seed = 1 }

  -- 4. Train with the thesis' settings: 20 epochs, minibatches of 8, Adam(0.00025, 0.8, 0.9).
  --    keep = "best" leaves the network with the weights of its best validation epoch.
  local r = sn.train { nets = { net }, data = data, epochs = 20, batch = 8,
                       adam = { lr = 0.00025, beta1 = 0.8, beta2 = 0.9 }, seed = 1, keep = "best" }
  local result = r[1]
  print(string.format("%-5s %s: best validation MSE %.3g at epoch %d, trained in %.1f s on %s",
                      c.name, tostring(net), result.best_val_mse, result.best_epoch, result.wall_time, result.backend))

  -- 5. Render the model and the network side by side on the cloth and on the unseen mesh.
  local row = { name = c.name, net = tostring(net), val_mse = result.best_val_mse, seconds = result.wall_time }
  for _, m in ipairs { { scene = small_cloth, label = "training mesh", key = "train_mse" },
                       { scene = blob, label = "test mesh", key = "test_mse" } } do
    local truth = m.scene:render(c.model, { view = 2 })
    local mine = m.scene:render(net, { view = 2 })
    -- Show the mesh, not the empty frame around it; a display clamps colours to [0, 1] (the
    -- model's image already is), so the network's is compared as it would be seen.
    local x, y, w, h = sn.image.covered_box(truth)
    truth, mine = sn.image.crop(truth, x, y, w, h), sn.image.clamp(sn.image.crop(mine, x, y, w, h))
    local mse = sn.image.mse(truth, mine, { channels = 3, mask = truth })
    local heat = sn.image.heatmap(sn.image.diff(truth, mine), { mask = truth, max = 0.1, label = "|error|" })
    panels[#panels + 1] = { image = truth, caption = c.name .. " (the model)" }
    panels[#panels + 1] = { image = mine, caption = string.format("network, MSE %.2g", mse) }
    panels[#panels + 1] = { image = heat, caption = "error" }
    row[m.key] = mse
  end
  rows[#rows + 1] = row
end

-- 6. The figure and a small table.
sn.fs.mkdir(out)
local figure = sn.image.grid { panels = panels, columns = 3, title = "shadenet quickstart: networks that shade",
                               row_labels = { "Phong, training mesh", "Phong, test mesh", "GGX, training mesh", "GGX, test mesh" } }
figure:save(out .. "/quickstart.png")

local lines = {
  "| model | network | validation MSE | image MSE, training mesh | image MSE, test mesh | training time (s) |",
  "|---|---|---:|---:|---:|---:|",
}
for _, r in ipairs(rows) do
  lines[#lines + 1] = string.format("| %s | %s | %.3g | %.3g | %.3g | %.1f |", r.name, r.net, r.val_mse, r.train_mse,
                                    r.test_mse, r.seconds)
end
-- Written to a temporary name and renamed: never a half-written table.
local tmp = out .. "/.table.md.tmp"
local f = assert(io.open(tmp, "w"))
f:write(table.concat(lines, "\n"), "\n")
f:close()
assert(os.rename(tmp, out .. "/table.md"))

print(string.format("wrote %s/quickstart.png and %s/table.md in %.0f s", out, out, sn.clock() - t_start))

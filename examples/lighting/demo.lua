-- What the lighting-model examples do with a model (examples/lighting/*.lua): hold its shader
-- to its twin (sn.lighting.check), stress it, train a network on the cloth in 5 poses from three
-- heights, and draw truth | network | error on meshes the network never saw.
local sn = require "shadenet"

local demo = {}

-- run(model, { out, name, title, inputs = {"normal", "view"}, hidden = {16 x 6}, epochs = 20 })
--   -> { check, stress, val_mse, unseen_mse, figure }
function demo.run(model, o)
  local t0 = sn.clock()
  local check = sn.lighting.check(model)
  print(string.format("%s: GPU shader vs Lua twin, largest difference %.3g over %d points (%d within 1e-3 of "
                      .. "n.l = 0, n.v = 0 or v = -l skipped)", tostring(model), check.max_difference, check.compared,
                      check.skipped))
  local stress = sn.lighting.stress(model)
  print(string.format("stress test: %d samples, %d failures (GPU NaN %d, Inf %d, negative %d; twin NaN %d)",
                      stress.samples, stress.failures, stress.gpu.nan, stress.gpu.inf, stress.gpu.negative,
                      stress.twin.nan))

  local inputs = o.inputs or { "normal", "view" }
  local poses = { {}, { rotate = { 60, 1, 0, 0 } }, { rotate = { -60, 1, 0, 0 } },
                  { rotate = { 60, 0, 0, 1 } }, { rotate = { -60, 0, 0, 1 } } }
  local cloth = sn.scene { mesh = "meshes/cloth.glb", size = { 320, 240 }, poses = poses,
                           views = { { count = 4, elevation = -30 }, { count = 4, elevation = 20 },
                                     { count = 4, elevation = 60 } } }
  local data = cloth:dataset { inputs = inputs, target = model, seed = 1 }
  local net = sn.mlp { inputs = data:inputs(), hidden = o.hidden or { 16, 16, 16, 16, 16, 16 }, outputs = 3, seed = 1 }
  local run = sn.train { nets = { net }, data = data, epochs = o.epochs or 20, batch = 8,
                         adam = { lr = 0.00025, beta1 = 0.8, beta2 = 0.9 }, seed = 1, keep = "best" }
  local n_train, n_val = data:counts()
  print(string.format("%s on %d + %d rows: best validation MSE %.3g (epoch %d, %.1f s)", tostring(net), n_train, n_val,
                      run[1].best_val_mse, run[1].best_epoch, run[1].wall_time))

  local meshes = {
    { label = "sphere", mesh = sn.mesh.sphere {} },
    { label = "torus", mesh = sn.mesh.torus {} },
    { label = "Duck", mesh = "../shared/meshes/Duck.gltf" },
  }
  local truths, mines, heats, captions = {}, {}, {}, {}
  local unseen = 0
  for k, m in ipairs(meshes) do
    local scene = sn.scene { mesh = m.mesh, size = { 200, 200 }, views = { count = 3, elevation = 25 } }
    local truth = scene:render(model, { view = 2 })
    local mine = sn.image.clamp(scene:render(net, { view = 2 }))
    local mse = sn.image.mse(truth, mine, { channels = 3, mask = truth })
    unseen = unseen + mse / #meshes
    truths[k], mines[k] = truth, mine
    heats[k] = sn.image.heatmap(sn.image.diff(truth, mine), { mask = truth, max = 0.2, label = "|error|" })
    captions[k] = string.format("image MSE %.2g", mse)
  end
  local panels = {}
  for k, m in ipairs(meshes) do panels[#panels + 1] = { image = truths[k], caption = m.label } end
  for k in ipairs(meshes) do panels[#panels + 1] = { image = mines[k], caption = captions[k] } end
  for k in ipairs(meshes) do panels[#panels + 1] = { image = heats[k], caption = "" } end
  sn.fs.mkdir(o.out)
  local file = o.out .. "/" .. o.name .. ".png"
  sn.image.grid { panels = panels, columns = #meshes, row_labels = { "the model", "network", "|error|" },
                  title = o.title .. ": the model, a network, |error| on unseen meshes" }:save(file)
  print(string.format("image MSE on the unseen meshes %.3g; wrote %s (%.0f s)", unseen, file, sn.clock() - t0))
  return { check = check, stress = stress, val_mse = run[1].best_val_mse, unseen_mse = unseen, figure = file }
end

return demo

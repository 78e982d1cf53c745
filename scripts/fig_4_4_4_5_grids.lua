-- Figures 4.4 and 4.5: what GGX networks of different depth (width 6: 4..14 hidden layers) and
-- width (6 hidden layers: 4..14 neurons) render, beside the ground truth, with |error| heatmaps
-- on one colour scale, on the training mesh and on a different test mesh from two views.
--   shadenet scripts/fig_4_4_4_5_grids.lua [--quick] [--shard i/n] [--out DIR] [--backend cpu|gl|auto]
package.path = (arg and arg[0] and arg[0]:match("^(.*)/[^/]*$") or ".") .. "/?.lua;" .. package.path
local exp = require "lib.experiment"

local E = exp.start("fig_4_4_4_5_grids", arg)
local sizes = { 4, 6, 8, 10, 12, 14 }
local epochs = E:pick(10, exp.epochs)
local desc = E:data_desc { model = "ggx" }
local runs, seen = {}, {}
local function add(layers, width)
  local id = string.format("L%02d-W%02d", layers, width)
  if not seen[id] then
    seen[id] = true
    runs[#runs + 1] = exp.run { id = id, hidden = exp.rep(width, layers), seed = 1, epochs = epochs, data = desc,
                                keep_params = true }
  end
  return id
end
local fig44, fig45 = {}, {}
for _, d in ipairs(sizes) do fig44[#fig44 + 1] = { id = add(d, 6), label = d .. " layers" } end
for _, w in ipairs(sizes) do fig45[#fig45 + 1] = { id = add(6, w), label = "width " .. w } end
local records = E:sweep(runs)

local meshes = {
  { mesh = exp.meshes.train, label = "training mesh", views = { 1 } },
  { mesh = exp.meshes.test, label = "test mesh", views = E:pick({ 2 }, { 2, 5 }) },
}
local rows = {}
local function figure(list, file, title)
  local nets = {}
  for _, n in ipairs(list) do
    local rec = records[n.id]
    if rec then nets[#nets + 1] = { net = exp.net_from_record(rec), label = n.label, id = n.id } end
  end
  if #nets == 0 then return end
  local mses = E:compare { file = file, title = title, model = "ggx", nets = nets, meshes = meshes }
  for _, n in ipairs(nets) do
    local row = { figure = title:match("Figure ([%d.]+)"), network = n.label, hidden = n.id,
                  val_mse = records[n.id].result.best_val_mse }
    for _, m in ipairs(mses) do
      if m.network == n.label then
        local key = m.mesh == "training mesh" and "train_mesh_mse" or "test_mesh_mse"
        row[key] = (row[key] or 0) + m.mse / (m.mesh == "training mesh" and #meshes[1].views or #meshes[2].views)
      end
    end
    rows[#rows + 1] = exp.with_unseen(row, records, { n.id })
  end
end
figure(fig44, "figures/fig_4_4_depth.png", "Figure 4.4 — GGX, width 6: 4 to 14 hidden layers")
figure(fig45, "figures/fig_4_5_width.png", "Figure 4.5 — GGX, 6 hidden layers: width 4 to 14")

E.R:table {
  title = "Figures 4.4 and 4.5 — validation MSE and image MSE on the training and the test mesh",
  columns = {
    { key = "figure" }, { key = "network", align = "left" }, { key = "hidden", header = "run", align = "left" },
    { key = "val_mse", header = "min val MSE", format = "%.4g" },
    { key = "train_mesh_mse", header = "image MSE, training mesh", format = "%.4g" },
    { key = "test_mesh_mse", header = "image MSE, test mesh (mean of views)", format = "%.4g" },
    exp.unseen_columns[1], exp.unseen_columns[2],
  },
  rows = rows,
  notes = { string.format("One seed per network; %s, tanh; training data: %s. Image MSE over covered pixels, RGB.",
                          exp.recipe(epochs), E:data_note()), exp.unseen_note() },
}
E:finish {
  records = records,
  config = { model = "ggx", sizes = sizes, epochs = epochs, batch = exp.batch, adam = exp.adam, data = desc, meshes = meshes },
  summary = { rows = rows },
}

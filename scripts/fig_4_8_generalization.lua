-- Figures 4.3 and 4.8: a network trained on the cloth renders a different mesh. Phong with 6
-- hidden layers x 6 (figure 4.3) and GGX with 8 x 12 (figure 4.8): the ground truth, the network
-- and the |error| on the training mesh and from three views of the test mesh.
--   shadenet scripts/fig_4_8_generalization.lua [--quick] [--shard i/n] [--out DIR] [--backend cpu|gl|auto]
package.path = (arg and arg[0] and arg[0]:match("^(.*)/[^/]*$") or ".") .. "/?.lua;" .. package.path
local exp = require "lib.experiment"

local E = exp.start("fig_4_8_generalization", arg)
local epochs = E:pick(10, exp.epochs)
local cases = {
  { id = "phong-6x6", model = "phong", hidden = exp.rep(6, 6), figure = "4.3", label = "Phong, 6 x 6" },
  { id = "ggx-8x12", model = "ggx", hidden = exp.rep(12, 8), figure = "4.8", label = "GGX, 8 x 12" },
}
local runs = {}
for _, c in ipairs(cases) do
  c.desc = E:data_desc { model = c.model }
  runs[#runs + 1] = exp.run { id = c.id, hidden = c.hidden, seed = 1, epochs = epochs, data = c.desc, keep_params = true }
end
local records = E:sweep(runs)

local rows = {}
for _, c in ipairs(cases) do
  local rec = records[c.id]
  if rec then
    local net = exp.net_from_record(rec)
    -- One figure per mesh view: truth | network, error under it; training mesh first.
    local mses = E:compare {
      file = string.format("figures/fig_%s_%s.png", (c.figure:gsub("%.", "_")), c.model),
      title = string.format("Figure %s — %s trained on the cloth, tested on another mesh", c.figure, c.label),
      model = c.model, nets = { { net = net, label = c.label } },
      meshes = { { mesh = exp.meshes.train, label = "training mesh", views = { 1 } },
                 { mesh = exp.meshes.test, label = "test mesh", views = E:pick({ 1, 4 }, { 1, 3, 6 }) } },
    }
    for _, m in ipairs(mses) do
      rows[#rows + 1] = { figure = c.figure, network = c.label, mesh = m.mesh, view = m.view, image_mse = m.mse,
                          val_mse = rec.result.best_val_mse }
    end
    rows[#rows + 1] = { figure = c.figure, network = c.label, mesh = "unseen meshes (mean)", image_mse = rec.result.unseen_mse,
                        ssim = rec.result.unseen_ssim, val_mse = rec.result.best_val_mse }
  end
end
-- How much of the test mesh lies outside what training saw: the share of its samples whose
-- normal points further up (world y) than any training normal does.
local function normals_y(mesh)
  local data = E:data { model = "phong", mesh = mesh }
  local n = data:counts()
  local ys = {}
  for i = 1, n do
    local x = data:row("train", i)
    ys[i] = x[2]
  end
  return ys
end
local max_train_y = -1
for _, y in ipairs(normals_y(exp.meshes.train)) do max_train_y = math.max(max_train_y, y) end
local test_y = normals_y(exp.meshes.test)
local outside = 0
for _, y in ipairs(test_y) do if y > max_train_y then outside = outside + 1 end end
local outside_share = outside / #test_y

E.R:table {
  title = "Figures 4.3 and 4.8 — image MSE on the training mesh and on the test mesh",
  columns = {
    { key = "figure" }, { key = "network", align = "left" }, { key = "mesh", align = "left" }, { key = "view" },
    { key = "image_mse", header = "image MSE", format = "%.4g" }, { key = "ssim", header = "SSIM", format = "%.4f" },
    { key = "val_mse", header = "min val MSE (training data)", format = "%.4g" },
  },
  rows = rows,
  notes = {
    string.format("One seed; %s, tanh; training data: %s. Image MSE over covered pixels, RGB.",
                  exp.recipe(epochs), E:data_note()),
    exp.unseen_note(),
    string.format("Coverage: no training normal points further up than y = %.3f; %.1f%% of the test mesh's samples do. Those are where the networks extrapolate.",
                  max_train_y, 100 * outside_share),
  },
}
E:finish {
  records = records,
  config = { cases = cases, epochs = epochs, batch = exp.batch, adam = exp.adam },
  summary = { rows = rows, max_train_normal_y = max_train_y, test_share_outside = outside_share },
}

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
-- How much of the test mesh lies outside what training saw (ds:coverage: equal-area bins of
-- normals and of views about the normal), drawn beside the figures.
local train_data = E:data { model = "phong" }
local test_scene = E:scene { mesh = exp.meshes.test }
local cov = train_data:coverage { against = test_scene, figure = E.R:path("figures/coverage.png"),
                                  title = "training rows (" .. E.data_choice .. ") against the test mesh" }
E.R.written[#E.R.written + 1] = "figures/coverage.png"

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
    string.format("Coverage (figures/coverage.png): the training rows fill %.1f%% of the normal sphere's bins and %.1f%% "
                  .. "of the view hemisphere's; their normals reach y = %.3f; %.1f%% of the test mesh's pixels fall in bins "
                  .. "they leave empty. Those are where the networks extrapolate.", 100 * cov.normal.fraction,
                  100 * cov.view.fraction, cov.normal.y_max, 100 * cov.outside.either),
  },
}
E:finish {
  records = records,
  config = { cases = cases, epochs = epochs, batch = exp.batch, adam = exp.adam },
  summary = { rows = rows, max_train_normal_y = cov.normal.y_max, normal_coverage = cov.normal.fraction,
              view_coverage = cov.view.fraction, test_share_outside = cov.outside.either },
}

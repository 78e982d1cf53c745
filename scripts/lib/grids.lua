-- Figures of what networks of several depths or widths render beside the ground truth, with
-- |error| heatmaps on one colour scale per mesh, on the training mesh and on a different test mesh
-- (the thesis' figures 4.1 and 4.2 on Phong, 4.4 and 4.5 on GGX), and a table of their
-- validation and image MSEs. One seed per network, as the thesis shows one image each.
--   M.run(E, { model = "phong", figures = { { file = "figures/x.png", title = "Figure 4.1 — ...",
--              nets = { { layers = 8, width = 6, label = "8 layers" }, ... } }, ... },
--              table_title = "..." })
local exp = require "lib.experiment"
local options = require "lib.options"

local M = {}

function M.run(E, o)
  options.check(o, "grids.run", { "model", "figures", "table_title" }, { "model", "figures" })
  local epochs = E:pick(10, exp.epochs)
  local desc = E:data_desc { model = o.model }
  local runs, seen = {}, {}
  for _, fig in ipairs(o.figures) do
    for _, n in ipairs(fig.nets) do
      n.id = string.format("L%02d-W%02d", n.layers, n.width)
      if not seen[n.id] then
        seen[n.id] = true
        runs[#runs + 1] = exp.run { id = n.id, hidden = exp.rep(n.width, n.layers), seed = 1, epochs = epochs,
                                    data = desc, keep_params = true }
      end
    end
  end
  local records = E:sweep(runs)

  local meshes = {
    { mesh = exp.meshes.train, label = "training mesh", views = { 1 } },
    { mesh = exp.meshes.test, label = "test mesh", views = E:pick({ 2 }, { 2, 5 }) },
  }
  local rows = {}
  for _, fig in ipairs(o.figures) do
    local nets, ids = {}, {}  -- E:compare's entries take net and label only
    for _, n in ipairs(fig.nets) do
      local rec = records[n.id]
      if rec then
        nets[#nets + 1] = { net = exp.net_from_record(rec), label = n.label }
        ids[#nets] = n.id
      end
    end
    if #nets > 0 then
      -- 640 x 480 in full mode: the cropped panels stay above 256 pixels wide, enough to see the effects.
      local mses = E:compare { file = fig.file, title = fig.title, model = o.model, nets = nets, meshes = meshes,
                               colour_shift = true, size = E:pick({ 200, 150 }, { 640, 480 }) }
      for k, n in ipairs(nets) do
        local id = ids[k]
        local row = { figure = fig.title:match("Figure ([%d.]+)"), network = n.label, hidden = id,
                      val_mse = records[id].result.best_val_mse }
        for _, m in ipairs(mses) do
          if m.network == n.label then
            local key = m.mesh == "training mesh" and "train_mesh_mse" or "test_mesh_mse"
            local views = m.mesh == "training mesh" and #meshes[1].views or #meshes[2].views
            row[key] = (row[key] or 0) + m.mse / views
            if m.mesh == "training mesh" then row.colour_shift = (row.colour_shift or 0) + m.colour_shift / views end
          end
        end
        rows[#rows + 1] = exp.with_unseen(row, records, { id })
      end
    end
  end

  E.R:table {
    title = o.table_title,
    columns = {
      { key = "figure" }, { key = "network", align = "left" }, { key = "hidden", header = "run", align = "left" },
      { key = "val_mse", header = "min val MSE", format = "%.4g" },
      { key = "train_mesh_mse", header = "image MSE, training mesh", format = "%.4g" },
      { key = "test_mesh_mse", header = "image MSE, test mesh (mean of views)", format = "%.4g" },
      { key = "colour_shift", header = "colour shift, training mesh", format = "%.4f" },
      exp.unseen_columns[1], exp.unseen_columns[2],
    },
    rows = rows,
    notes = { string.format("One seed per network; %s, tanh; training data: %s. Image MSE over covered pixels, RGB.",
                            exp.recipe(epochs), E:data_note()),
              exp.colour_shift_note,
              exp.unseen_note() },
  }
  E:finish {
    records = records,
    config = { model = o.model, figures = o.figures, epochs = epochs, batch = exp.batch, adam = exp.adam, data = desc,
               meshes = meshes },
    summary = { rows = rows },
  }
  return rows
end

return M

-- The sweep of tables 4.1 and 4.2: hidden layers x widths (2..12 each), seeds, the thesis'
-- training settings; reported as the median over seeds of each run's minimum validation MSE,
-- beside the thesis' value, with a plot of MSE against width per depth.
local exp = require "lib.experiment"
local thesis = require "lib.thesis"
local stats = require "lib.stats"
local options = require "lib.options"

local M = {}

-- M.run(E, { model = "phong", thesis = thesis.table_4_1, title = "...", sizes = {...} })
function M.run(E, o)
  options.check(o, "depth_width.run", { "model", "thesis", "title", "sizes" }, { "model", "thesis" })
  local sizes = o.sizes or thesis.sizes
  local seeds = E:pick(2, 10)
  local epochs = E:pick(10, exp.epochs)
  local desc = E:data_desc { model = o.model }
  local runs, ids = {}, {}
  for seed = 1, seeds do
    for _, layers in ipairs(sizes) do
      for _, width in ipairs(sizes) do
        local id = string.format("L%02d-W%02d-s%02d", layers, width, seed)
        runs[#runs + 1] = exp.run { id = id, hidden = exp.rep(width, layers), seed = seed, epochs = epochs, data = desc }
        local k = layers .. "x" .. width
        ids[k] = ids[k] or {}
        table.insert(ids[k], id)
      end
    end
  end
  local records = E:sweep(runs)

  local base = E:baseline(desc)
  local rows = {}
  for _, layers in ipairs(sizes) do
    for _, width in ipairs(sizes) do
      local list = ids[layers .. "x" .. width]
      local m, found, bad = exp.median_of(records, list, "best_val_mse")
      local t = o.thesis[layers] and o.thesis[layers][width]
      rows[#rows + 1] = exp.with_unseen({
        layers = layers, width = width, val_mse = m, thesis_val_mse = t,
        ratio = (m and t) and m / t or nil, runs = found, diverged = bad,
        best_epoch = exp.median_of(records, list, "best_epoch"),
        vs_constant = m and m / base.constant or nil,
      }, records, list)
    end
  end
  -- Do the same architectures do well here and in the thesis?
  local vs = exp.vs_thesis(rows, "val_mse", "thesis_val_mse")
  local spearman, median_ratio = vs.spearman, vs.median_ratio
  E.R:table {
    title = o.title,
    grids = { { title = "median minimum validation MSE, ours (thesis)", rows = "layers", cols = "width",
                row_header = "hidden layers", col_header = "width", value = "val_mse", thesis = "thesis_val_mse",
                format = "%.4g" } },
    columns = exp.add_unseen_columns({
      { key = "layers", header = "hidden layers" }, { key = "width", header = "width" },
      { key = "val_mse", header = "val MSE (ours)", format = "%.4g" },
      { key = "thesis_val_mse", header = "val MSE (thesis)", format = "%.4g" },
      { key = "ratio", header = "ours / thesis", format = "%.2f" },
      { key = "vs_constant", header = "ours / constant predictor", format = "%.4f" },
      { key = "best_epoch", header = "median best epoch", format = "%.1f" },
      { key = "runs", header = "runs" }, { key = "diverged", header = "diverged" },
    }, "vs_constant"),
    rows = rows,
    notes = {
      string.format("Median over %d seeds of each run's minimum validation MSE over %s, tanh; training data: %s.",
                    seeds, exp.recipe(epochs), E:data_note()),
      exp.unseen_note(),
      string.format("Constant predictor (training mean) on the same validation rows: MSE %.6f; all-zeros output: %.6f.",
                    base.constant, base.zeros),
      vs.notes[1], vs.notes[2],
    },
  }

  -- MSE against width, one line per depth; the thesis' as dashed points for comparison.
  local series = {}
  for _, layers in ipairs(sizes) do
    local s = { name = string.format("%d layers", layers), x = {}, y = {}, style = "linespoints" }
    for _, r in ipairs(rows) do
      if r.layers == layers and r.val_mse then
        s.x[#s.x + 1] = r.width
        s.y[#s.y + 1] = r.val_mse
      end
    end
    series[#series + 1] = s
  end
  local th = { name = "thesis (all depths)", x = {}, y = {}, style = "points", color = "#999999" }
  for _, r in ipairs(rows) do
    if r.thesis_val_mse then th.x[#th.x + 1] = r.width th.y[#th.y + 1] = r.thesis_val_mse end
  end
  series[#series + 1] = th
  E:plot("plots/mse_vs_width.png", { title = o.title, xlabel = "neurons per hidden layer",
                                     ylabel = "median min. validation MSE", logy = true, series = series, xtics = "2" })

  return E:finish {
    records = records,
    config = { model = o.model, sizes = sizes, seeds = seeds, epochs = epochs, batch = exp.batch, adam = exp.adam,
               data = desc },
    summary = { rows = rows, constant_mse = base.constant, zeros_mse = base.zeros, spearman_vs_thesis = spearman,
                median_ratio_vs_thesis = median_ratio, data = E.data_choice },
  }
end

return M

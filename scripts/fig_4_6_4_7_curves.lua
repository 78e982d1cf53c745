-- Figures 4.6 and 4.7: validation curves of GGX networks over many epochs with a small learning
-- rate (Adam lr 0.00003, betas 0.8 / 0.9, batch 8; 800 epochs in full mode): one curve per depth
-- (width 8) and one per width (8 hidden layers; the thesis' caption repeats "width 8" for both
-- figures, 8 layers is the depth its other GGX experiments use). Each curve is the per-epoch
-- median over seeds.
--   shadenet scripts/fig_4_6_4_7_curves.lua [--quick] [--shard i/n] [--out DIR] [--backend cpu|gl|auto]
package.path = (arg and arg[0] and arg[0]:match("^(.*)/[^/]*$") or ".") .. "/?.lua;" .. package.path
local exp = require "lib.experiment"
local stats = require "lib.stats"

local E = exp.start("fig_4_6_4_7_curves", arg)
local adam = { lr = 0.00003, beta1 = exp.adam.beta1, beta2 = exp.adam.beta2 }
local epochs = E:pick(20, 800)
local seeds = E:pick(1, 3)
local depths = { 2, 4, 6, 8, 10, 12 }
local widths = { 2, 4, 6, 8, 10, 12 }
local desc = E:data_desc { model = "ggx" }

-- One run per distinct architecture and seed (8 x 8 belongs to both figures).
local archs, seen = {}, {}
local function add(layers, width)
  local id = string.format("L%02d-W%02d", layers, width)
  if not seen[id] then
    seen[id] = true
    archs[#archs + 1] = { id = id, layers = layers, width = width }
  end
  return id
end
local depth_ids, width_ids = {}, {}
for _, d in ipairs(depths) do depth_ids[#depth_ids + 1] = add(d, 8) end
for _, w in ipairs(widths) do width_ids[#width_ids + 1] = add(8, w) end
local runs = {}
for seed = 1, seeds do
  for _, a in ipairs(archs) do
    runs[#runs + 1] = exp.run { id = string.format("%s-s%02d", a.id, seed), hidden = exp.rep(a.width, a.layers),
                                seed = seed, epochs = epochs, adam = adam, data = desc }
  end
end
local records = E:sweep(runs)

-- Per-epoch median curve of an architecture over its seeds.
local function curve(id)
  local y = {}
  for e = 1, epochs do
    local vals = {}
    for seed = 1, seeds do
      local rec = records[string.format("%s-s%02d", id, seed)]
      if rec and rec.result.val_mse[e] then vals[#vals + 1] = rec.result.val_mse[e] end
    end
    y[e] = stats.median(vals) or 0 / 0
  end
  return y
end

local rows = {}
local function series_for(ids, label_of, figure)
  local series = {}
  for _, id in ipairs(ids) do
    local a
    for _, x in ipairs(archs) do if x.id == id then a = x end end
    local y = curve(id)
    local x = {}
    for e = 1, epochs do x[e] = e end
    series[#series + 1] = { name = label_of(a), x = x, y = y }
    local best, best_e = math.huge, nil
    for e = 1, epochs do if y[e] == y[e] and y[e] < best then best, best_e = y[e], e end end
    local final = y[epochs]
    local run_ids = {}
    for seed = 1, seeds do run_ids[seed] = string.format("%s-s%02d", id, seed) end
    rows[#rows + 1] = exp.with_unseen({
      figure = figure, layers = a.layers, width = a.width, best_val_mse = best_e and best or nil, best_epoch = best_e,
      final_val_mse = final, rise_after_best = (best_e and final == final) and final / best or nil,
      epoch_to_2x_best = nil,
    }, records, run_ids)
    -- How fast it gets there: the first epoch within 2x of its own best.
    if best_e then
      for e = 1, epochs do
        if y[e] <= 2 * best then rows[#rows].epoch_to_2x_best = e break end
      end
    end
  end
  return series
end

local base = E:baseline(desc)
local const = { name = "constant predictor", x = { 1, epochs }, y = { base.constant, base.constant }, color = "#888888" }
local s6 = series_for(depth_ids, function(a) return a.layers .. " hidden layers" end, "4.6")
s6[#s6 + 1] = const
E:plot("plots/fig_4_6_depth.png", {
  title = string.format("Figure 4.6 — GGX, width 8, lr 0.00003: validation MSE by depth (median of %d seeds)", seeds),
  xlabel = "epoch", ylabel = "validation MSE", logy = true, logx = epochs >= 100, series = s6 })
local s7 = series_for(width_ids, function(a) return "width " .. a.width end, "4.7")
s7[#s7 + 1] = const
E:plot("plots/fig_4_7_width.png", {
  title = string.format("Figure 4.7 — GGX, 8 hidden layers, lr 0.00003: validation MSE by width (median of %d seeds)", seeds),
  xlabel = "epoch", ylabel = "validation MSE", logy = true, logx = epochs >= 100, series = s7 })

E.R:table {
  title = "Figures 4.6 and 4.7 — where each validation curve bottoms out and ends",
  columns = exp.add_unseen_columns({
    { key = "figure" }, { key = "layers", header = "hidden layers" }, { key = "width" },
    { key = "best_val_mse", header = "min val MSE", format = "%.4g" }, { key = "best_epoch", header = "at epoch" },
    { key = "epoch_to_2x_best", header = "first epoch within 2x of min" },
    { key = "final_val_mse", header = "final val MSE", format = "%.4g" },
    { key = "rise_after_best", header = "final / min", format = "%.3f" },
  }, "rise_after_best"),
  rows = rows,
  notes = {
    string.format("Per-epoch median of %d seeds; %s, tanh; training data: %s. Constant predictor: %.6f.",
                  seeds, exp.recipe(epochs, adam), E:data_note(), base.constant),
    exp.unseen_note() .. " Unseen-mesh columns: each run's best-epoch weights, median over seeds.",
    "final / min > 1: the validation MSE rose again after its minimum (the thesis sees this for wider layers).",
  },
}
E:finish {
  records = records,
  config = { model = "ggx", depths = depths, widths = widths, seeds = seeds, epochs = epochs, adam = adam, batch = exp.batch,
             data = desc },
  summary = { rows = rows, constant_mse = base.constant },
}

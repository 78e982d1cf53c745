-- Figure 4.11: validation curves of a GGX network (8 hidden layers x 8) with each activation
-- the thesis tried: tanh, sigmoid, ReLU and leaky ReLU with a = 0.05, 0.1, 0.2 (Adam lr 0.00003,
-- 800 epochs in full mode); beside them the activations shadenet added (sine, softplus,
-- squareplus, ELU, GELU, swish, exponential), and the thesis' four with the output activation
-- matching the hidden one ("out" rows): the thesis saw sigmoid and ReLU stall at the all-zeros
-- output's MSE, which needs outputs that can be pinned at 0 (a ReLU output can; a linear one
-- cannot). The dead-unit diagnostics (per hidden layer: ReLU units active on no sample,
-- sigmoid/tanh units saturated, the others flat (|f'| < 0.01), on more than 99% of the samples)
-- say why a curve stalls.
--   shadenet scripts/fig_4_11_activations.lua [--quick] [--shard i/n] [--out DIR] [--backend cpu|gl|auto]
package.path = (arg and arg[0] and arg[0]:match("^(.*)/[^/]*$") or ".") .. "/?.lua;" .. package.path
local exp = require "lib.experiment"
local stats = require "lib.stats"
local thesis = require "lib.thesis"

local E = exp.start("fig_4_11_activations", arg)
local adam = { lr = 0.00003, beta1 = exp.adam.beta1, beta2 = exp.adam.beta2 }
local epochs = E:pick(20, 800)
local seeds = E:pick(1, 3)
local acts = {
  { id = "tanh", label = "tanh", activation = "tanh" },
  { id = "sigmoid", label = "sigmoid", activation = "sigmoid" },
  { id = "relu", label = "ReLU", activation = "relu" },
  { id = "leaky005", label = "leaky ReLU a=0.05", activation = "leaky_relu", slope = 0.05 },
  { id = "leaky010", label = "leaky ReLU a=0.1", activation = "leaky_relu", slope = 0.1 },
  { id = "leaky020", label = "leaky ReLU a=0.2", activation = "leaky_relu", slope = 0.2 },
  { id = "sine", label = "sine (w0 = 1)", activation = "sine" },
  { id = "softplus", label = "softplus", activation = "softplus" },
  { id = "squareplus", label = "squareplus", activation = "squareplus" },
  { id = "elu", label = "ELU", activation = "elu" },
  { id = "gelu", label = "GELU (tanh form)", activation = "gelu" },
  { id = "swish", label = "swish", activation = "swish" },
  { id = "exponential", label = "exponential", activation = "exponential" },
  { id = "tanh-out", label = "tanh (out tanh)", activation = "tanh", output_activation = "tanh" },
  { id = "sigmoid-out", label = "sigmoid (out sigmoid)", activation = "sigmoid", output_activation = "sigmoid" },
  { id = "relu-out", label = "ReLU (out ReLU)", activation = "relu", output_activation = "relu" },
  { id = "leaky010-out", label = "leaky ReLU a=0.1 (out leaky)", activation = "leaky_relu", slope = 0.1,
    output_activation = "leaky_relu" },
}
local desc = E:data_desc { model = "ggx" }
local runs = {}
for seed = 1, seeds do
  for _, a in ipairs(acts) do
    runs[#runs + 1] = exp.run { id = string.format("%s-s%02d", a.id, seed), hidden = exp.rep(8, 8), seed = seed,
                                epochs = epochs, adam = adam, activation = a.activation, slope = a.slope,
                                output_activation = a.output_activation, data = desc }
  end
end
local records = E:sweep(runs)
local base = E:baseline(desc)

local rows, series = {}, {}
for _, a in ipairs(acts) do
  local x, y = {}, {}
  for e = 1, epochs do
    local vals = {}
    for seed = 1, seeds do
      local rec = records[string.format("%s-s%02d", a.id, seed)]
      if rec and rec.result.val_mse[e] then vals[#vals + 1] = rec.result.val_mse[e] end
    end
    x[e], y[e] = e, stats.median(vals) or 0 / 0
  end
  -- The thesis' four solid, the added activations dashed, the "out" variants dotted.
  local thesis_four = a.id == "tanh" or a.id == "sigmoid" or a.id == "relu" or a.id:match("^leaky%d+$")
  series[#series + 1] = { name = a.label, x = x, y = y, dash = a.output_activation and 3 or (not thesis_four and 2 or nil) }
  local ids = {}
  for seed = 1, seeds do ids[seed] = string.format("%s-s%02d", a.id, seed) end
  local best, found, diverged = exp.median_of(records, ids, "best_val_mse")
  -- Dead units: per hidden layer, the mean over seeds; the row shows the mean over layers and
  -- the worst layer.
  local per_layer = exp.dead_units_per_layer(records, ids)
  local layer_text = {}
  for l, f in ipairs(per_layer) do layer_text[l] = string.format("%.2f", f) end
  -- Output channels stuck at one value (a ReLU output pinned at 0), per seed.
  local stuck = {}
  for seed, id in ipairs(ids) do
    local rec = records[id]
    stuck[seed] = rec and rec.result.stuck_outputs and tostring(rec.result.stuck_outputs) or "-"
  end
  local final = stats.finite(y[epochs]) and y[epochs] or nil  -- no seed reached the last epoch: no number
  rows[#rows + 1] = exp.with_unseen({
    activation = a.label, best_val_mse = best, final_val_mse = final, runs = found, diverged = diverged,
    vs_zeros = best and best / base.zeros or nil, vs_constant = best and best / base.constant or nil,
    stalled = best and (best > 0.9 * base.constant and "yes" or "no") or nil,
    dead_mean = stats.mean(per_layer), dead_max = stats.max(per_layer), dead_per_layer = table.concat(layer_text, " "),
    stuck_outputs = table.concat(stuck, " "),
  }, records, ids)
end
series[#series + 1] = { name = "all-zeros output", x = { 1, epochs }, y = { base.zeros, base.zeros }, color = "#888888" }
series[#series + 1] = { name = "constant predictor", x = { 1, epochs }, y = { base.constant, base.constant }, color = "#bbbbbb" }
E:plot("plots/fig_4_11_activations.png", {
  title = string.format("Figure 4.11 — GGX, 8 x 8, lr 0.00003: validation MSE by activation (median of %d seeds)", seeds),
  xlabel = "epoch", ylabel = "validation MSE", logy = true, logx = epochs >= 100, series = series,
  width = 1100, key = "outside right top" })

E.R:table {
  title = "Figure 4.11 — activations: best and final validation MSE, dead units and stuck outputs",
  columns = exp.add_unseen_columns({
    { key = "activation", align = "left" },
    { key = "best_val_mse", header = "min val MSE", format = "%.4g" },
    { key = "final_val_mse", header = "final val MSE", format = "%.4g" },
    { key = "vs_zeros", header = "min / all-zeros MSE", format = "%.3f" },
    { key = "vs_constant", header = "min / constant MSE", format = "%.3f" },
    { key = "stalled", header = "stalled (> 0.9 x constant)" },
    { key = "dead_mean", header = "dead units (mean over layers)", format = "%.2f" },
    { key = "dead_max", header = "dead units (worst layer)", format = "%.2f" },
    { key = "dead_per_layer", header = "dead units per hidden layer", align = "left" },
    { key = "stuck_outputs", header = "stuck output channels, per seed", align = "left" },
    { key = "runs", header = "runs" }, { key = "diverged", header = "diverged" },
  }, "final_val_mse"),
  rows = rows,
  notes = {
    string.format("Median of %d seeds; %s; default (Xavier) initialisation for every activation; training data: %s.",
                  seeds, exp.recipe(epochs, adam), E:data_note()),
    exp.unseen_note(),
    string.format("Our all-zeros output MSE is %.6f and the constant predictor's %.6f (the thesis' all-zeros MSE on its data: %.5f).",
                  base.zeros, base.constant, thesis.fig_4_11.stall_mse),
    "Stuck output channels: of the 3, those with the same finite value (to the bit) on every validation row — a ReLU output pinned at 0 is what the thesis' stall at the all-zeros error needs.",
    "Dead units, per hidden layer over the validation rows: ReLU / leaky ReLU units never positive; tanh units with |a| > 0.99 and sigmoid units below 0.01 or above 0.99, and units of the other activations with |f'(z)| < 0.01, on more than 99% of the rows.",
    "Rows marked \"out\" use the hidden activation at the output too (the others a linear output). An empty row diverged: eight exponential layers overflow float (its result records `diverged`).",
  },
}
E:finish {
  records = records,
  config = { model = "ggx", hidden = exp.rep(8, 8), activations = acts, seeds = seeds, epochs = epochs, adam = adam,
             batch = exp.batch, data = desc },
  summary = { rows = rows, zeros_mse = base.zeros, constant_mse = base.constant, thesis_stall_mse = thesis.fig_4_11.stall_mse },
}

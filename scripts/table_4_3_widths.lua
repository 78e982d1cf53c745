-- Table 4.3 (and figure 4.10): GGX with 8 hidden layers of fixed and of varying width: 6 fixed,
-- 13 fixed, 6 -> 13 (6 neurons on the input side, 13 on the output side, 4 + 4 layers) and
-- 13 -> 6; median of 10 seeds of the minimum validation MSE over 20 epochs, beside the thesis'.
-- The figure renders the first seed's networks beside the ground truth.
--   shadenet scripts/table_4_3_widths.lua [--quick] [--shard i/n] [--out DIR] [--backend cpu|gl|auto]
package.path = (arg and arg[0] and arg[0]:match("^(.*)/[^/]*$") or ".") .. "/?.lua;" .. package.path
local exp = require "lib.experiment"
local thesis = require "lib.thesis"

local E = exp.start("table_4_3_widths", arg)
local rep = exp.rep
local function concat(a, b)
  local t = {}
  for _, v in ipairs(a) do t[#t + 1] = v end
  for _, v in ipairs(b) do t[#t + 1] = v end
  return t
end
local archs = {
  { name = "6 fixed", id = "w6", hidden = rep(6, 8) },
  { name = "13 fixed", id = "w13", hidden = rep(13, 8) },
  { name = "6 -> 13", id = "w6to13", hidden = concat(rep(6, 4), rep(13, 4)) },
  { name = "13 -> 6", id = "w13to6", hidden = concat(rep(13, 4), rep(6, 4)) },
}
local seeds = E:pick(2, 10)
local epochs = E:pick(10, exp.epochs)
local desc = E:data_desc { model = "ggx" }
local runs = {}
for seed = 1, seeds do
  for _, a in ipairs(archs) do
    runs[#runs + 1] = exp.run { id = string.format("%s-s%02d", a.id, seed), hidden = a.hidden, seed = seed,
                                epochs = epochs, data = desc, keep_params = seed == 1 }
  end
end
local records = E:sweep(runs)

local base = E:baseline(desc)
local rows = {}
for _, a in ipairs(archs) do
  local ids = {}
  for seed = 1, seeds do ids[seed] = string.format("%s-s%02d", a.id, seed) end
  local m, found, bad = exp.median_of(records, ids, "best_val_mse")
  local t = thesis.table_4_3[a.name]
  rows[#rows + 1] = exp.with_unseen({
    widths = a.name, hidden = exp.arch_name(a.hidden), parameters = exp.param_count(6, a.hidden, 3),
    val_mse = m, thesis_val_mse = t, ratio = (m and t) and m / t or nil,
    vs_constant = m and m / base.constant or nil, runs = found, diverged = bad,
  }, records, ids)
end
local vs_thesis = exp.vs_thesis(rows, "val_mse", "thesis_val_mse")
E.R:table {
  title = "Table 4.3 — GGX, 8 hidden layers: fixed against varying widths",
  columns = exp.add_unseen_columns({
    { key = "widths", header = "hidden widths", align = "left" }, { key = "hidden", header = "layers", align = "left" },
    { key = "parameters", header = "parameters" },
    { key = "val_mse", header = "val MSE (ours)", format = "%.4g" },
    { key = "thesis_val_mse", header = "val MSE (thesis)", format = "%.4g" },
    { key = "ratio", header = "ours / thesis", format = "%.2f" },
    { key = "vs_constant", header = "ours / constant predictor", format = "%.4f" },
    { key = "runs", header = "runs" }, { key = "diverged", header = "diverged" },
  }, "vs_constant"),
  rows = rows,
  notes = {
    string.format("Median over %d seeds of each run's minimum validation MSE over %s, tanh; training data: %s.",
                  seeds, exp.recipe(epochs), E:data_note()),
    exp.unseen_note(),
    string.format("Constant predictor on the same validation rows: MSE %.6f; all-zeros output: %.6f.", base.constant, base.zeros),
    vs_thesis.notes[1], vs_thesis.notes[2],
  },
}

-- Figure 4.10: the ground truth and the four networks (seed 1) on the training mesh.
local nets = {}
for _, a in ipairs(archs) do
  local rec = records[a.id .. "-s01"]
  if rec then nets[#nets + 1] = { net = exp.net_from_record(rec), label = a.name } end
end
if #nets > 0 then
  E:compare { file = "figures/fig_4_10_widths.png", title = "Figure 4.10 — GGX, 8 hidden layers, fixed and varying widths",
              model = "ggx", nets = nets, meshes = { { mesh = exp.meshes.train, label = "training mesh", views = { 1 } } } }
end

E:finish {
  records = records,
  config = { model = "ggx", archs = archs, seeds = seeds, epochs = epochs, batch = exp.batch, adam = exp.adam, data = desc },
  summary = { rows = rows, constant_mse = base.constant, zeros_mse = base.zeros },
}

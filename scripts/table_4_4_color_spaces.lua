-- Table 4.4: GGX networks with 8 hidden layers of width 4, 8 and 16 that output RGB, HSV or CIE
-- L*a*b* (scaled to about [0, 1]: L*/100, (a*+128)/255, (b*+128)/255); median of 10 seeds of the
-- minimum validation MSE over 20 epochs, measured, as in the thesis, in the space the network
-- outputs, and also in RGB after converting its outputs back (the thesis' numbers in different
-- spaces are not on one scale; the RGB column is). Figure 4.12: seed 1's networks of width 4 and
-- 16 in each space rendered beside the truth, with their colour shift.
--   shadenet scripts/table_4_4_color_spaces.lua [--quick] [--shard i/n] [--out DIR] [--backend cpu|gl|auto]
package.path = (arg and arg[0] and arg[0]:match("^(.*)/[^/]*$") or ".") .. "/?.lua;" .. package.path
local exp = require "lib.experiment"
local thesis = require "lib.thesis"

local E = exp.start("table_4_4_color_spaces", arg)
local spaces = { { id = "rgb", label = "RGB" }, { id = "hsv", label = "HSV" }, { id = "cie", label = "CIE L*a*b*" } }
local widths = { 4, 8, 16 }
local seeds = E:pick(2, 10)
local epochs = E:pick(10, exp.epochs)
local runs, descs = {}, {}
for _, s in ipairs(spaces) do descs[s.id] = E:data_desc { model = "ggx", color = s.id } end
for seed = 1, seeds do
  for _, s in ipairs(spaces) do
    for _, w in ipairs(widths) do
      runs[#runs + 1] = exp.run { id = string.format("%s-W%02d-s%02d", s.id, w, seed), hidden = exp.rep(w, 8), seed = seed,
                                  epochs = epochs, data = descs[s.id], keep_params = true }
    end
  end
end
local records = E:sweep(runs)

-- RGB-space MSE of a network that outputs `space`: its validation outputs decoded to RGB
-- against the RGB validation targets (the same rows: the split depends on the seed only).
local rgb_data = E:data(descs.rgb)
local rows = {}
for _, s in ipairs(spaces) do
  for _, w in ipairs(widths) do
    local ids, rgb_mses = {}, {}
    for seed = 1, seeds do
      local id = string.format("%s-W%02d-s%02d", s.id, w, seed)
      ids[seed] = id
      local rec = records[id]
      if rec then rgb_mses[#rgb_mses + 1] = exp.rgb_val_mse(exp.net_from_record(rec), rgb_data) end
    end
    local m, found, bad = exp.median_of(records, ids, "best_val_mse")
    local t = thesis.table_4_4[s.id][w]
    rows[#rows + 1] = exp.with_unseen({
      space = s.label, width = w, val_mse = m, thesis_val_mse = t, ratio = (m and t) and m / t or nil,
      rgb_val_mse = require("lib.stats").median(rgb_mses), runs = found, diverged = bad,
    }, records, ids)
  end
end
-- Figure 4.12: what seed 1's networks of width 4 and 16 render in each space (decoded to RGB).
local fig_nets = {}
for _, w in ipairs { 4, 16 } do
  for _, s in ipairs(spaces) do
    local rec = records[string.format("%s-W%02d-s01", s.id, w)]
    if rec then fig_nets[#fig_nets + 1] = { net = exp.net_from_record(rec), label = s.label .. ", width " .. w } end
  end
end
local shifts = {}
if #fig_nets > 0 then
  local panels = E:compare { file = "figures/fig_4_12_color_spaces.png", model = "ggx", nets = fig_nets, colour_shift = true,
                             title = "Figure 4.12 — GGX, 8 hidden layers: RGB, HSV and CIE L*a*b* outputs at widths 4 and 16",
                             meshes = { { mesh = exp.meshes.train, label = "training mesh", views = { 1 } } } }
  for _, p in ipairs(panels) do shifts[p.network] = p.colour_shift end
end
for _, r in ipairs(rows) do r.colour_shift = shifts[r.space .. ", width " .. r.width] end
local base = E:baseline(descs.rgb)
local vs_thesis = exp.vs_thesis(rows, "val_mse", "thesis_val_mse")  -- own-space MSEs, as the thesis printed them
E.R:table {
  title = "Table 4.4 — GGX, 8 hidden layers: output colour space x width",
  grids = {
    { title = "median minimum validation MSE in the network's own space, ours (thesis)", rows = "space", cols = "width",
      row_header = "space", value = "val_mse", thesis = "thesis_val_mse", format = "%.4g" },
    { title = "the same networks' validation MSE in RGB (outputs converted back)", rows = "space", cols = "width",
      row_header = "space", value = "rgb_val_mse", format = "%.4g" },
  },
  columns = exp.add_unseen_columns({
    { key = "space", align = "left" }, { key = "width" },
    { key = "val_mse", header = "val MSE, own space (ours)", format = "%.4g" },
    { key = "thesis_val_mse", header = "val MSE (thesis)", format = "%.4g" },
    { key = "ratio", header = "ours / thesis", format = "%.2f" },
    { key = "rgb_val_mse", header = "val MSE in RGB", format = "%.4g" },
    { key = "colour_shift", header = "colour shift, seed 1 (fig. 4.12)", format = "%.4f" },
    { key = "runs", header = "runs" }, { key = "diverged", header = "diverged" },
  }, "rgb_val_mse"),
  rows = rows,
  notes = {
    string.format("Median over %d seeds; %s, tanh; training data: %s. The RGB column evaluates each run's "
                  .. "best-epoch weights.", seeds, exp.recipe(epochs), E:data_note()),
    exp.unseen_note(),
    string.format("RGB constant predictor on the validation rows: MSE %.6f.", base.constant),
    "The thesis printed RGB only at width 8.",
    exp.colour_shift_note .. " Figure 4.12 (figures/fig_4_12_color_spaces.png) shows seed 1's networks of widths 4 and 16.",
    vs_thesis.notes[1], vs_thesis.notes[2],
  },
}
E:finish {
  records = records,
  config = { model = "ggx", spaces = spaces, widths = widths, seeds = seeds, epochs = epochs, batch = exp.batch,
             adam = exp.adam, data = descs },
  summary = { rows = rows, constant_mse_rgb = base.constant },
}

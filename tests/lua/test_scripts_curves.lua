-- scripts/fig_4_6_4_7_curves.lua and fig_4_11_activations.lua --quick: curves written as plots
-- with their data, a row per curve, numbers that match the plotted data.
local C = require "script_check"

local dir = C.tmpdir("curves")
C.ok("scripts/fig_4_6_4_7_curves.lua", { "--quick", "--out", dir })
C.assert_files(dir, { "table.md", "table.csv", "run.json", "plots/fig_4_6_depth.png", "plots/fig_4_6_depth.csv",
                      "plots/fig_4_7_width.png", "plots/fig_4_7_width.csv" })
local rows = C.csv(dir .. "/table.csv")
assert(#rows == 12, "6 depth curves + 6 width curves, got " .. #rows)
C.assert_range(rows, "best_val_mse", 1e-7, 0.05, "curves")
C.assert_range(rows, "rise_after_best", 1, 10, "curves")
local info = C.json(dir .. "/run.json")
assert(info.config.adam.lr == 0.00003, "the curves' learning rate is the thesis' 0.00003")
-- The plotted data: one series per depth plus the constant predictor, epochs 1..N.
local pts = C.csv(dir .. "/plots/fig_4_6_depth.csv")
local by = {}
for _, p in ipairs(pts) do
  by[p.series] = by[p.series] or {}
  table.insert(by[p.series], p)
end
local epochs = info.config.epochs
assert(#by["2 hidden layers"] == epochs and #by["12 hidden layers"] == epochs, "a point per epoch")
local min2 = math.huge
for _, p in ipairs(by["2 hidden layers"]) do min2 = math.min(min2, p.y) end
for _, r in ipairs(rows) do
  if r.figure == 4.6 and r.layers == 2 then
    assert(math.abs(r.best_val_mse - min2) <= 1e-9 * min2, "the table's minimum is the plotted curve's")
  end
end
assert(by["constant predictor"], "the constant predictor is drawn for scale")
C.rm(dir)

dir = C.tmpdir("act")
C.ok("scripts/fig_4_11_activations.lua", { "--quick", "--out", dir })
C.assert_files(dir, { "table.md", "table.csv", "run.json", "plots/fig_4_11_activations.png", "plots/fig_4_11_activations.csv" })
rows = C.csv(dir .. "/table.csv")
assert(#rows == 17, "the thesis' six, seven added activations and four with a matching output: " .. #rows)
local act, learned = {}, {}
for _, r in ipairs(rows) do
  act[r.activation] = r
  if r.activation ~= "exponential" then learned[#learned + 1] = r end
end
-- Every network that does not diverge ends below the all-zeros MSE, where the thesis' stall
-- sits (quick mode's 20 epochs at lr 0.00003 leave the sigmoids near their start).
local zeros = C.json(dir .. "/run.json").baselines[1].zeros
assert(zeros > 0.2, "the calibrated GGX's all-zeros MSE: " .. zeros)
C.assert_range(learned, "best_val_mse", 1e-7, 0.5 * zeros, "activations")
C.assert_range(rows, "dead_mean", 0, 1, "activations")
for _, name in ipairs { "sine (w0 = 1)", "softplus", "squareplus", "ELU", "GELU (tanh form)", "swish",
                        "ReLU (out ReLU)", "sigmoid (out sigmoid)", "tanh (out tanh)", "leaky ReLU a=0.1 (out leaky)" } do
  assert(act[name], "a row for " .. name)
end
-- eight exponential layers overflow at once: the row records the divergence, no number
assert(act.exponential and not C.finite(act.exponential.best_val_mse), "exponential diverges")
-- It diverges before its first validation (no best_val_mse in its record): still a run, and a
-- diverged one; its final MSE is no number, not "nan".
assert(act.exponential.runs == 1 and act.exponential.diverged == 1,
       "the diverged run is counted: runs " .. tostring(act.exponential.runs) .. ", diverged " .. tostring(act.exponential.diverged))
assert(act.tanh.runs == 1 and act.tanh.diverged == 0, "tanh: one run, not diverged")
assert(not C.read(dir .. "/table.md"):find("nan", 1, true), "no 'nan' in the table:\n" .. C.read(dir .. "/table.md"))
assert(act["GELU (tanh form)"].stalled == "no", "GELU learns")
assert(act.tanh.dead_per_layer and #act.tanh.dead_per_layer:gsub("[^ ]", "") == 7, "8 hidden layers of dead-unit fractions")
assert(act.tanh.stalled == "no", "tanh learns")
-- stuck output channels, one count of the 3 per seed (quick mode: one seed)
for _, r in ipairs(learned) do
  local n = tonumber(r.stuck_outputs)
  assert(n and n >= 0 and n <= 3, r.activation .. ": stuck output channels " .. tostring(r.stuck_outputs))
end
assert(tostring(act.tanh.stuck_outputs) == "0", "a linear tanh network's outputs all follow the input")
-- Sigmoid's plateau: at 20 quick epochs and lr 0.00003 it has not left the constant predictor.
assert(act.sigmoid.vs_constant > 0.9, "sigmoid stalls near the constant predictor: " .. act.sigmoid.vs_constant)
assert(act.tanh.best_val_mse < act.sigmoid.best_val_mse, "tanh beats sigmoid")
C.rm(dir)
print("curve scripts: ok")

-- Ctrl-C or SIGTERM in a script of several sweeps: the later sweeps do not start (they trained in
-- full, then the script exited 130), the tables, plots and figures say their results are partial,
-- and the re-run completes them; every run record names the build that trained it, and run.json
-- lists every build its runs came from.
local sn = require "shadenet"
local C = require "script_check"
local json = require "lib.json"
local results = require "lib.results"

local script, root = C.child("stops", [[
package.path = "scripts/?.lua;" .. package.path
local exp = require "lib.experiment"
local E = exp.start("two_sweeps", arg)
local desc = E:data_desc { model = "phong", data = "cloth", size = { 64, 48 }, views = 2, samples = 300 }
local function runs(tag)
  local t = {}
  for seed = 1, 2 do
    t[seed] = exp.run { id = tag .. seed, hidden = { 4 }, seed = seed, epochs = 1, data = desc, keep_params = true }
  end
  return t
end
local a = E:sweep(runs("a"), { chunk = 1 })
local b = E:sweep(runs("b"), { chunk = 1 })
local nets, x, y = {}, {}, {}
for _, id in ipairs { "a1", "a2", "b1", "b2" } do
  local rec = a[id] or b[id]
  if rec then
    nets[#nets + 1] = { net = exp.net_from_record(rec), label = id }
    x[#x + 1], y[#y + 1] = #x + 1, rec.result.best_val_mse
  end
end
E.R:table { columns = { { key = "networks" } }, rows = { { networks = #nets } } }
E:plot("plots/val.png", { title = "runs", series = { { name = "val", x = x, y = y, style = "points" } } })
E:compare { file = "figures/nets.png", title = "networks", model = "phong", nets = nets, size = { 48, 36 },
            meshes = { { mesh = "meshes/test_blob.glb", label = "blob", view_count = 2 } } }
E:finish {}
]])

-- Ctrl-C after the first sweep's first run (a job of one run each): the first sweep stops, the
-- second never starts, exit 130.
local D = root .. "/stopped"
local code, out = C.run_interrupted(script, { "--quick", "--out", D })
assert(code == 130, "exit 130 after Ctrl-C, got " .. tostring(code) .. ":\n" .. out)
assert(out:find("two_sweeps: stopped (Ctrl-C or SIGTERM); 1 of 2 runs finished and kept", 1, true) and
       out:find("two_sweeps: not started (stopped by Ctrl-C or SIGTERM); 0 of 2 runs already finished", 1, true), out)
assert(#sn.fs.list(D .. "/runs") == 1, "one run trained: " .. table.concat(sn.fs.list(D .. "/runs"), " "))
local info = C.json(D .. "/run.json")
assert(info.interrupted and info.sweeps[2].not_started and info.sweeps[2].finished == 0, json.encode(info.sweeps))
assert(C.read(D .. "/table.md"):find("**Partial results:** the sweep was stopped (Ctrl-C or SIGTERM) with 1 of 4 runs "
                                     .. "finished (1 later sweep of 2 runs not started); – marks the others", 1, true),
       C.read(D .. "/table.md"))
-- The plot's and the figure's titles say so, and the figure's CSV on every row (a figure of 1 of
-- its 4 networks looked whole).
assert(C.read(D .. "/plots/val.gp"):find("set title 'runs (partial: the sweep was stopped, see table.md)'", 1, true),
       C.read(D .. "/plots/val.gp"))
local rows = C.csv(D .. "/figures/nets.csv")
assert(#rows == 1 and rows[1].network == "a1" and rows[1].partial == "partial: the sweep was stopped, see table.md",
       C.read(D .. "/figures/nets.csv"))

-- SIGTERM the same way: 143.
code, out = C.run_interrupted(script, { "--quick", "--out", root .. "/terminated" }, nil, 15)
assert(code == 143 and out:find("not started (stopped by Ctrl-C or SIGTERM)", 1, true), tostring(code) .. ":\n" .. out)

-- The re-run trains the rest: whole results, no partial mark.
out = C.ok(script, { "--quick", "--out", D })
assert(#sn.fs.list(D .. "/runs") == 4 and not C.read(D .. "/table.md"):find("Partial") and
       not C.read(D .. "/plots/val.gp"):find("partial") and not C.read(D .. "/figures/nets.csv"):find("partial"), out)
info = C.json(D .. "/run.json")
assert(not info.interrupted and info.builds == sn.build and info.runs_per_build[sn.build] == 4, json.encode(info))
assert(not out:find("trained by"), "one build: nothing to say\n" .. out)

-- A run trained by another build (a resumed sweep): said, and run.json names both.
local f = D .. "/runs/b2.json"
local rec = C.json(f)
assert(rec.build == sn.build, "a record names its build: " .. tostring(rec.build))
rec.build = "0123456789ab-other"
results.write_file(f, json.encode(rec))
out = C.ok(script, { "--quick", "--out", D })
assert(out:find("two_sweeps: the tables' runs were trained by 2 builds (", 1, true) and
       out:find("0123456789ab-other: 1", 1, true) and out:find(sn.build .. ": 3", 1, true), out)
info = C.json(D .. "/run.json")
assert(info.runs_per_build[sn.build] == 3 and info.runs_per_build["0123456789ab-other"] == 1 and
       info.builds:find("0123456789ab-other", 1, true) and info.environment.build == sn.build, json.encode(info))

C.rm(root)
print("stops: ok")

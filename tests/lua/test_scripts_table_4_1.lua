-- scripts/table_4_1_phong.lua --quick: the table's shape and numbers, shard + merge = one run,
-- a resumed run = an uninterrupted one, Ctrl-C keeps finished runs and the re-run completes them.
local sn = require "shadenet"
local C = require "script_check"
local thesis = require "lib.thesis"
local results = require "lib.results"
local json = require "lib.json"

local script = "scripts/table_4_1_phong.lua"
local root = C.tmpdir("t41")
local A = root .. "/whole"
C.ok(script, { "--quick", "--out", A })
C.assert_files(A, { "table.md", "table.csv", "run.json", "plots/mse_vs_width.png", "plots/mse_vs_width.csv" })

local rows, head = C.csv(A .. "/table.csv")
assert(#rows == 36, "36 rows (6 depths x 6 widths), got " .. #rows)
for _, k in ipairs { "layers", "width", "val_mse", "thesis_val_mse", "ratio", "vs_constant", "runs", "diverged" } do
  local found = false
  for _, h in ipairs(head) do found = found or h == k end
  assert(found, "table.csv lacks column " .. k)
end
C.assert_range(rows, "val_mse", 1e-6, 0.2, "table_4_1")
local info = C.json(A .. "/run.json")
local constant = info.baselines[1].constant
assert(C.finite(constant) and constant > 0.01, "the constant predictor's MSE is recorded: " .. tostring(constant))
local best, below = math.huge, 0
for _, r in ipairs(rows) do
  assert(r.thesis_val_mse == thesis.table_4_1[r.layers][r.width], "thesis value beside ours")
  assert(r.runs == 2 and r.diverged == 0, "2 quick seeds per cell, none diverged")
  best = math.min(best, r.val_mse)
  if r.val_mse < constant / 5 then below = below + 1 end
end
-- The default data (the cloth in 5 poses from 3 rings) is harder than the hanging cloth alone:
-- quick mode's 10 epochs on it leave the best cell about 36x below the constant predictor.
assert(best < constant / 20, string.format("the best network (%.6f) beats the constant predictor (%.6f) by 20x", best, constant))
assert(below >= 30, below .. " of 36 architectures beat the constant predictor by 5x")
-- Wider and deeper helps: the 12 x 12 cell beats the 2 x 2 cell.
local function cell(l, w) for _, r in ipairs(rows) do if r.layers == l and r.width == w then return r.val_mse end end end
assert(cell(12, 12) < cell(2, 2) / 1.4, "12x12 learns Phong better than 2x2")
assert(info.quick == true and info.backend.used == "cpu" and info.environment.gl.renderer, "run.json records mode, backend, renderer")
local hostname = assert(io.open("/proc/sys/kernel/hostname")):read("*l")
assert(info.environment.host == hostname:match("^%s*(.-)%s*$"), "and the machine's name")
-- And the build: the git commit of this checkout (CI clones it), "-dirty" with changes.
local git = io.popen("git rev-parse HEAD 2>/dev/null"):read("*l")
local build = info.environment.build
assert(build == sn.build and (git and git:sub(1, 12) == build:sub(1, 12) or build == "unknown"),
       ("the build %s, the checkout %s"):format(tostring(build), tostring(git)))
-- A full run does not go into a quick run's folder, nor another experiment or another choice of
-- data: their run ids are the same, and one overwrote the other's records and tables.
local code, refused = C.run(script, { "--out", A })
assert(code == 2 and refused:find(A .. " holds the results of table_4_1_phong --quick (--data poses, --ggx thesis); "
                                  .. "table_4_1_phong (--data poses, --ggx thesis) there would overwrite them: give it "
                                  .. "its own --out DIR", 1, true), tostring(code) .. ": " .. refused)
code, refused = C.run("scripts/table_4_2_ggx.lua", { "--quick", "--out", A })
assert(code == 2 and refused:find("; table_4_2_ggx --quick (--data poses, --ggx thesis) there would overwrite", 1, true),
       refused)
code, refused = C.run(script, { "--quick", "--data", "cloth", "--out", A })
assert(code == 2 and refused:find("; table_4_1_phong --quick (--data cloth, --ggx thesis) there", 1, true), refused)
local md = C.read(A .. "/table.md")
assert(md:find("| hidden layers \\ width |", 1, true) and md:find("(0.002158)", 1, true), "markdown grid with thesis values")
assert(not md:find("GGX", 1, true), "a Phong table's notes name no GGX")
assert(md:find("**Quick mode (--quick):**", 1, true) and not md:find("One shard", 1, true), "a quick table says so:\n" .. md)

-- Sharded in two, merged: the same table.
local S1, S2, M = root .. "/s1", root .. "/s2", root .. "/merged"
C.ok(script, { "--quick", "--shard", "1/2", "--out", S1 })
C.ok(script, { "--quick", "--out", S2 }, { SLURM_ARRAY_TASK_ID = "1", SLURM_ARRAY_TASK_COUNT = "2", SLURM_ARRAY_TASK_MIN = "0" })
assert(#C.csv(S1 .. "/table.csv") == 36, "a shard's table lists every cell")
assert(C.read(S1 .. "/table.md"):find("**One shard (1/2):**", 1, true) and
       C.read(S2 .. "/table.md"):find("**One shard (2/2, from slurm):**", 1, true), "a shard's table says it is one")
-- merge.lua run inside a Slurm array task merges everything: the array's shard is not its own.
local out = C.ok("scripts/merge.lua", { S1, S2, "--out", M },
                 { SLURM_ARRAY_TASK_ID = "1", SLURM_ARRAY_TASK_COUNT = "2", SLURM_ARRAY_TASK_MIN = "0" })
assert(C.json(M .. "/run.json").shard == nil and not C.read(M .. "/table.md"):find("One shard", 1, true),
       "the merged run.json and table name no shard")
local code
assert(out:find("72 run files from 2 folders"), "merge copies both shards' runs:\n" .. out)
assert(C.read(M .. "/table.csv") == C.read(A .. "/table.csv"), "shard + merge = unsharded table")
local ra, rm = C.run_results(A), C.run_results(M)
for id, r in pairs(ra) do assert(rm[id] == r, "run " .. id .. " differs after merging") end
-- A record the output folder held before a merge gives way to the shards' (an earlier run's was
-- kept over them, and the merged table came out wrong or empty).
local run_file = M .. "/runs/L02-W02-s01.json"
local rec = json.decode(C.read(run_file), run_file)
rec.result.best_val_mse = 0.5
results.write_file(run_file, json.encode(rec))
out = C.ok("scripts/merge.lua", { S1, S2, "--out", M })
assert(out:find("(71 already there; 1 records the folder held before replaced by the shards')", 1, true), out)
assert(C.read(M .. "/table.csv") == C.read(A .. "/table.csv"), "the shards' record back in the table")
-- One shard alone, merged: its table says it is partial and stderr names runs left out (it
-- looked complete, its cells medians of one seed, and stderr promised – marks).
out = C.ok("scripts/merge.lua", { S1, "--out", root .. "/half" })
assert(out:find("36 of 72 runs are not among the merged run files %(L02%-W04%-s01, ") and
       C.read(root .. "/half/table.md"):find("**Partial results (merged):** 36 of 72 runs", 1, true), out)

-- Shards run with --data and --ggx merge into the table those options give: merge.lua re-runs
-- the experiment with the options the shards' run.json records (Table 4.3: 8 quick runs).
local W = root .. "/widths"
local wopts = { "--quick", "--data", "cloth", "--ggx", "gold" }
local function with(list, more) local t = { unpack(list) } for _, a in ipairs(more) do t[#t + 1] = a end return t end
C.ok("scripts/table_4_3_widths.lua", with(wopts, { "--out", W .. "/whole" }))
C.ok("scripts/table_4_3_widths.lua", with(wopts, { "--shard", "1/2", "--out", W .. "/s1" }))
C.ok("scripts/table_4_3_widths.lua", with(wopts, { "--shard", "2/2", "--out", W .. "/s2" }))
out = C.ok("scripts/merge.lua", { W .. "/s1", W .. "/s2", "--out", W .. "/merged" })
assert(not out:find("not among the merged"), "every run is merged:\n" .. out)
assert(C.read(W .. "/merged/table.csv") == C.read(W .. "/whole/table.csv"), "--data cloth --ggx gold: shard + merge = unsharded")
assert(C.read(W .. "/merged/table.md"):find("(--data cloth, the thesis' data); GGX: the gold metal (--ggx gold", 1, true),
       "the merged table names the shards' data")
-- --backend decides which finished runs are reused: runs the cpu trained are trained again for
-- --backend gl (said once, with their number), auto takes both, and run.json names every
-- backend its records were trained on.
local B = W .. "/backends"
C.copy_runs(W .. "/whole", B, function() return true end)
out = C.ok("scripts/table_4_3_widths.lua", with(wopts, { "--backend", "gl", "--shard", "1/2", "--out", B }))
assert(out:find("4 finished runs in [^\n]* were trained on the cpu backend; %-%-backend gl trains them again"),
       "reused runs of another backend are trained again, and it says so:\n" .. out)
local binfo = C.json(B .. "/run.json")
assert(binfo.backend.used == "gl" and binfo.backend.runs_per_backend.gl == 4, "the shard used its 4 gl runs")
C.ok("scripts/table_4_3_widths.lua", with(wopts, { "--out", B }))
binfo = C.json(B .. "/run.json")
assert(binfo.backend.used == "cpu, gl" and binfo.backend.runs_per_backend.cpu == 4 and binfo.backend.runs_per_backend.gl == 4,
       "--backend auto reuses both, and run.json names both: " .. json.encode(binfo.backend))

-- A run.json from before the options were recorded: its command line tells.
for _, s in ipairs { "s1", "s2" } do
  local f = W .. "/" .. s .. "/run.json"
  local info = C.json(f)
  info.options = nil
  results.write_file(f, json.encode(info))
end
C.ok("scripts/merge.lua", { W .. "/s1", W .. "/s2", "--out", W .. "/merged_old" })
assert(C.read(W .. "/merged_old/table.csv") == C.read(W .. "/whole/table.csv"), "options read from the command line")
-- Shards run with different options are refused.
local f2 = W .. "/s2/run.json"
local info2 = C.json(f2)
info2.options = { data = "cloth", ggx = "thesis" }
results.write_file(f2, json.encode(info2))
code, out = C.run("scripts/merge.lua", { W .. "/s1", W .. "/s2", "--out", W .. "/mixed" })
assert(code ~= 0 and out:find("s1 was run with %-%-ggx gold, [^\n]*s2 with %-%-ggx thesis: their runs are different experiments"),
       "mixed options refused:\n" .. out)
-- A full-mode shard beside a quick one: the message names which is which.
info2.options, info2.quick = nil, false
results.write_file(f2, json.encode(info2))
code, out = C.run("scripts/merge.lua", { W .. "/s1", W .. "/s2", "--out", W .. "/mixed" })
assert(code ~= 0 and out:find("s1 was run with %-%-quick, [^\n]*s2 without it: their runs are different experiments"),
       "quick and full refused, named the right way round:\n" .. out)

-- An experiment of one's own, outside scripts/: run.json records its real path and merge.lua
-- runs it from there, with the script's own flags the shards were given (it dropped them, and
-- no run matched); a one-run figure sweep trains in shard 1 only, and in shard 2 a network
-- asked of its missing record is a clear error, not "attempt to index local 'rec'".
local own, own_dir = C.child("own", [[
package.path = "scripts/?.lua;" .. package.path
local exp = require "lib.experiment"
local E = exp.start("my_own", arg, { flags = { { flag = "--lr", value = "X", help = "Adam's learning rate" } } })
local desc = E:data_desc { model = "phong" }
local adam = { lr = tonumber(E.opts.extra.lr or exp.adam.lr), beta1 = exp.adam.beta1, beta2 = exp.adam.beta2 }
local runs = {}
for seed = 1, 2 do runs[seed] = exp.run { id = "s" .. seed, hidden = { 4 }, seed = seed, epochs = 1, data = desc, adam = adam } end
local records = E:sweep(runs)
local fig = E:sweep { exp.run { id = "fig", hidden = { 4 }, seed = 3, epochs = 1, data = desc, keep_params = true } }
if not os.getenv("NO_FIGURE") then exp.net_from_record(fig.fig, "fig") end
E:finish { records = records }
]])
C.ok(own, { "--quick", "--lr", "0.001", "--shard", "1/2", "--out", own_dir .. "/s1" })
assert(C.json(own_dir .. "/s1/run.json").command:find("shadenet " .. own .. " --quick", 1, true), "run.json names the real script")
code, out = C.run(own, { "--quick", "--lr", "0.001", "--shard", "2/2", "--out", own_dir .. "/s2" })
assert(code ~= 0 and out:find("run 'fig' is not finished in this folder: under %-%-shard i/n"), "a clear error:\n" .. out)
C.ok(own, { "--quick", "--lr=0.001", "--shard", "2/2", "--out", own_dir .. "/s2" }, { NO_FIGURE = "1" })
assert(C.json(own_dir .. "/s2/run.json").flags["--lr"] == "0.001", "run.json records the script's own flags")
out = C.ok("scripts/merge.lua", { own_dir .. "/s1", own_dir .. "/s2", "--out", own_dir .. "/merged" })
assert(C.json(own_dir .. "/merged/run.json").sweeps[1].finished == 2, "the merge ran the script from its folder:\n" .. out)

-- Resumed: half the runs already there.
local R = root .. "/resumed"
local kept = C.copy_runs(A, R, function(i) return i % 2 == 0 end)
out = C.ok(script, { "--quick", "--out", R })
assert(out:find("resuming, " .. kept .. " of 72 runs already finished"), "resume message:\n" .. out)
assert(C.read(R .. "/table.csv") == C.read(A .. "/table.csv"), "a resumed run = an uninterrupted one")

-- Ctrl-C after the first training job (of 36 runs: by default all 72 train in one): exit 130,
-- finished runs kept; the re-run completes.
local I = root .. "/interrupted"
local code, iout = C.run_interrupted(script, { "--quick", "--runs-per-job", "36", "--out", I })
assert(code == 130, "an interrupted sweep exits 130, got " .. tostring(code) .. ":\n" .. iout)
assert(iout:find("stopped %(Ctrl%-C or SIGTERM%); 36 of 72 runs finished and kept"), "interrupt message:\n" .. iout)
out = C.ok(script, { "--quick", "--out", I })
assert(out:find("resuming, 36 of 72"), "the re-run resumes:\n" .. out)
assert(C.read(I .. "/table.csv") == C.read(A .. "/table.csv"), "interrupted + resumed = uninterrupted")

-- SIGTERM (a scheduler's time limit) after the first training job: the same graceful stop.
local K = root .. "/terminated"
code, iout = C.run_interrupted(script, { "--quick", "--runs-per-job", "36", "--out", K }, nil, 15)
assert(code == 143, "a terminated sweep exits 143 (128 + SIGTERM), got " .. tostring(code) .. ":\n" .. iout)
assert(iout:find("terminate (SIGTERM): finishing the work in flight", 1, true) and
       iout:find("stopped %(Ctrl%-C or SIGTERM%); 36 of 72 runs finished and kept"), "terminate message:\n" .. iout)

-- Ctrl-C inside the second group's training: sn.train stops at its next step, the runs it
-- stopped part-way are not recorded, and the re-run trains them again from the start.
local T = root .. "/in_training"
code, iout = C.run_interrupted(script, { "--quick", "--runs-per-job", "36", "--out", T }, 2)
assert(code == 130, "interrupted in training: exit 130, got " .. tostring(code) .. ":\n" .. iout)
assert(iout:find("interrupt: stopping training at the next step", 1, true) and
       iout:find("stopped %(Ctrl%-C or SIGTERM%); 36 of 72 runs finished and kept in [^\n]*; run the same command to "
                 .. "resume %(it trains the 36 stopped part%-way%)"),
       "interrupt message:\n" .. iout)
out = C.ok(script, { "--quick", "--out", T })
assert(out:find("resuming, 36 of 72"), "the re-run resumes:\n" .. out)
assert(C.read(T .. "/table.csv") == C.read(A .. "/table.csv"), "stopped in training + resumed = uninterrupted")

-- An unknown option lists the valid ones: a command-line error, exit 2, without a Lua traceback.
code, out = C.run(script, { "--quik" })
assert(code == 2 and out:find("unknown option '%-%-quik' %(valid: %-%-quick, %-%-shard i/n, %-%-out DIR"), out)
assert(not out:find("traceback") and out:find("--help lists the options", 1, true), out)

C.rm(root)
print("table_4_1 script: ok")

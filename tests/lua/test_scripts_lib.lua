-- scripts/lib: command line, JSON, atomic results files, tables, sweeps (shards, resume), plots.
package.path = "scripts/?.lua;" .. package.path
local sn = require "shadenet"
local cli = require "lib.cli"
local json = require "lib.json"
local results = require "lib.results"
local Sweep = require "lib.sweep"
local stats = require "lib.stats"
local plot = require "lib.plot"
local Progress = require "lib.progress"

local tmp = sn.fs.tempdir("test_scripts_lib")

-- ---- cli ----
local none = function() return nil end
local o = cli.parse({ "--quick", "--shard", "2/4", "--out", "x/y" }, "t", nil, none)
assert(o.quick == true and o.shard.index == 2 and o.shard.count == 4 and o.out == "x/y", "cli basic")
o = cli.parse({ "--shard=3/3", "--backend=cpu" }, "t", nil, none)
assert(o.shard.index == 3 and o.backend == "cpu" and not o.quick, "cli inline values")
local ok, err = pcall(cli.parse, { "--qiuck" }, "t", nil, none)
assert(not ok and err:find("unknown option '%-%-qiuck'") and err:find("%-%-quick") and err:find("%-%-shard i/n"),
       "unknown flag lists the valid ones: " .. tostring(err))
ok, err = pcall(cli.parse, { "--shard", "5/4" }, "t", nil, none)
assert(not ok and err:find("1..n"), "shard out of range: " .. tostring(err))
ok, err = pcall(cli.parse, { "--shard", "1/99999999999999999999" }, "t", nil, none)
assert(not ok and err:find("--shard 1/99999999999999999999: i must be 1..n and n 1..2^31", 1, true), tostring(err))
ok, err = pcall(cli.parse, { "--backend", "cuda" }, "t", nil, none)
assert(not ok and err:find("valid: cpu, gl, auto"), "bad backend: " .. tostring(err))
o = cli.parse({ "--ggx", "gold", "--data=cloth" }, "t", nil, none)
assert(o.ggx == "gold" and o.data == "cloth", "cli --ggx and --data")
ok, err = pcall(cli.parse, { "--ggx", "copper" }, "t", nil, none)
assert(not ok and err:find("unknown --ggx 'copper' (valid: thesis, gold)", 1, true), "bad preset: " .. tostring(err))
ok, err = pcall(cli.parse, { "--out" }, "t", nil, none)
assert(not ok and err:find("needs a value"), "missing value: " .. tostring(err))
local env = { SLURM_ARRAY_TASK_ID = "5", SLURM_ARRAY_TASK_COUNT = "8", SLURM_ARRAY_TASK_MIN = "0" }
o = cli.parse({}, "t", nil, function(k) return env[k] end)
assert(o.shard.index == 6 and o.shard.count == 8, "slurm 0-based array task 5 -> shard 6/8")
env.SLURM_ARRAY_TASK_MIN = "1"
o = cli.parse({}, "t", nil, function(k) return env[k] end)
assert(o.shard.index == 5, "slurm 1-based array")
-- A stepped array (sbatch --array=0-14:2): ids 0, 2, ..., 14 are shards 1..8.
local stepped = { SLURM_ARRAY_TASK_ID = "6", SLURM_ARRAY_TASK_COUNT = "8", SLURM_ARRAY_TASK_MIN = "0",
                  SLURM_ARRAY_TASK_STEP = "2" }
o = cli.parse({}, "t", nil, function(k) return stepped[k] end)
assert(o.shard.index == 4 and o.shard.count == 8, "stepped array task 6 -> shard 4/8")
stepped.SLURM_ARRAY_TASK_ID = "14"
assert(cli.parse({}, "t", nil, function(k) return stepped[k] end).shard.index == 8, "the last task of a stepped array")
stepped.SLURM_ARRAY_TASK_ID = "5"
ok, err = pcall(cli.parse, {}, "t", nil, function(k) return stepped[k] end)
assert(not ok and err:find("step 2"), "an id off the step: " .. tostring(err))
o = cli.parse({ "--shard", "1/2" }, "t", nil, function(k) return env[k] end)
assert(o.shard.index == 1 and o.shard.count == 2, "--shard wins over Slurm")
o = cli.parse({ "--epochs", "7" }, "t", { { flag = "--epochs", value = "N", help = "epochs" } }, none)
assert(o.extra.epochs == "7", "script-specific flag")

-- ---- json ----
local v = { a = 1, b = { 0.1, 2.5e-4, -3 }, c = "x\"y\n", d = { e = true, f = {} }, g = 0 / 0, h = math.huge }
local back = json.decode(json.encode(v, "  "))
assert(back.a == 1 and back.b[2] == 2.5e-4 and back.c == "x\"y\n" and back.d.e == true, "json round trip")
assert(back.g ~= back.g and back.h == math.huge, "json keeps NaN and Inf as numbers")
assert(json.encode({ b = 1, a = 2 }) == '{"a":2,"b":1}', "json sorts keys")
assert(json.encode({ 0.1, 1 / 3 }) == "[0.1,0.3333333333333333]", "json: shortest exact text")
assert(json.decode(json.encode({ 1 / 3 }))[1] == 1 / 3, "json keeps every bit")
ok, err = pcall(json.decode, '{"a": }', "f.json")
assert(not ok and err:find("f.json"), "json errors name the file")

-- ---- results ----
local p = results.write_file(tmp .. "/sub/a.txt", "hello")
assert(results.read_file(p) == "hello", "atomic write")
for _, name in ipairs(sn.fs.list(tmp .. "/sub")) do assert(not name:find("tmp"), "no temp file left: " .. name) end
-- Temporary files as the writers name them (.NAME.tmpDIGITS): a killed writer's, two minutes old, is
-- cleaned; a fresh one (a writer beside us) and a file that only looks alike stay.
for _, name in ipairs { ".a.txt.tmp4242", ".b.json.tmp7", ".c.txt.tmp12x", "d.txt.tmp5" } do
  local f = io.open(tmp .. "/sub/" .. name, "w") f:write("half") f:close()
end
os.execute(("touch -d '2 minutes ago' %q %q %q"):format(tmp .. "/sub/.a.txt.tmp4242", tmp .. "/sub/.c.txt.tmp12x",
                                                        tmp .. "/sub/d.txt.tmp5"))
assert(results.clean_temps(tmp .. "/sub") == 1, "a killed writer's temp file is cleaned")
assert(sn.fs.exists(tmp .. "/sub/.a.txt.tmp4242") == nil and sn.fs.exists(tmp .. "/sub/.b.json.tmp7") == "file" and
       sn.fs.exists(tmp .. "/sub/.c.txt.tmp12x") == "file" and sn.fs.exists(tmp .. "/sub/d.txt.tmp5") == "file")
assert(sn.fs.remove_stale_temporaries(tmp .. "/sub", 0) == 1, "age 0: the fresh one too")
for _, name in ipairs { ".c.txt.tmp12x", "d.txt.tmp5" } do os.remove(tmp .. "/sub/" .. name) end
-- Opening a results folder cleans its plots/ and figures/ too, where a killed gnuplot or image
-- writer left its temporary (only the folder itself and runs/ were cleaned).
for _, rel in ipairs { "/.table.md.tmp11", "/plots/.p.png.tmp12", "/figures/.f.png.tmp13", "/figures/.g.png.tmp14" } do
  results.write_file(tmp .. "/opened" .. rel, "half")
end
os.execute(("touch -d '2 minutes ago' %q %q %q"):format(tmp .. "/opened/.table.md.tmp11", tmp .. "/opened/plots/.p.png.tmp12",
                                                        tmp .. "/opened/figures/.f.png.tmp13"))
results.open({ out = tmp .. "/opened" }, "opened")
assert(#sn.fs.list(tmp .. "/opened/plots") == 0 and table.concat(sn.fs.list(tmp .. "/opened/figures")) == ".g.png.tmp14" and
       not sn.fs.exists(tmp .. "/opened/.table.md.tmp11"), "stale temporaries left in plots/ or figures/")
local cols = { { key = "layers" }, { key = "width" }, { key = "ours", format = "%.6f" }, { key = "thesis", format = "%.6f" } }
local rows = { { layers = 2, width = 4, ours = 0.0012346, thesis = 0.000736 }, { layers = 2, width = 6, ours = 0.5 } }
assert(results.csv(cols, rows) == "layers,width,ours,thesis\n2,4,0.0012346,0.000736\n2,6,0.5,\n", "csv")
local md = results.markdown(cols, rows)
assert(md:find("| 2 | 4 | 0.001235 | 0.000736 |", 1, true) and md:find("| 2 | 6 | 0.500000 | – |", 1, true), "markdown: " .. md)
-- Cells are literal text: Markdown's emphasis and code characters are escaped.
md = results.markdown({ { key = "space", header = "colour_space" } }, { { space = "CIE L*a*b*" }, { space = "a_b | `c`" } })
assert(md:find("| colour\\_space |", 1, true) and md:find("| CIE L\\*a\\*b\\* |", 1, true) and
       md:find("| a\\_b \\| \\`c\\` |", 1, true), "markdown escapes: " .. md)
local grid = results.markdown_grid({ rows = "layers", cols = "width", value = "ours", thesis = "thesis", format = "%.6f" }, rows)
assert(grid:find("| 2 | 0.001235 (0.000736) | 0.500000 |", 1, true), "grid: " .. grid)
ok, err = pcall(results.markdown_grid, { rows = "layers", cols = "width", value = "ours" },
                { rows[1], rows[2], { layers = 2, width = 4, ours = 0.3 } })
assert(not ok and err:find("two rows have layers = 2 and width = 4", 1, true), "a duplicate cell is an error: " .. tostring(err))

-- ---- stats ----
assert(stats.median({ 3, 1, 2 }) == 2 and stats.median({ 4, 1, 3, 2 }) == 2.5, "median")
local m, left = stats.median({ 1, 0 / 0, 3 })
assert(m == 2 and left == 1, "median skips and counts non-finite values")
assert(stats.median({}) == nil, "median of nothing")
-- exp.median_of: a run that diverged before any validation has no value; it is a run, diverged.
local exp = require "lib.experiment"
local recs = { a = { result = { best_val_mse = 1 } }, b = { result = { diverged = { epoch = 1 } } },
               c = { result = { best_val_mse = 3 } } }
local med, found, bad = exp.median_of(recs, { "a", "b", "c", "missing" }, "best_val_mse")
-- Spearman's rank correlation with ties: average ranks, Pearson's correlation of the ranks
-- (ours 1 2 2 3 5 4 against 1 1 2 3 4 5: 15.25 / 17).
local vrows = {}
for k, pair in ipairs { { 1, 1 }, { 2, 1 }, { 2, 2 }, { 3, 3 }, { 5, 4 }, { 4, 5 } } do
  vrows[k] = { ours = pair[1], thesis = pair[2] }
end
local vs = exp.vs_thesis(vrows, "ours", "thesis")
assert(math.abs(vs.spearman - 15.25 / 17) < 1e-12, "Spearman with ties: " .. tostring(vs.spearman))
vs = exp.vs_thesis({ { ours = 3, thesis = 1 }, { ours = 1, thesis = 1 }, { ours = 2, thesis = 1 } }, "ours", "thesis")
assert(vs.spearman == nil, "no rank correlation against a constant")
-- Dead units: the mean over the records found (2 of 3 seeds here), not over every seed.
local dead = exp.dead_units_per_layer({ s1 = { result = { dead_units = { 0.5, 0.25 } } },
                                        s2 = { result = { dead_units = { 0.25, 0 } } } }, { "s1", "s2", "s3" })
assert(dead[1] == 0.375 and dead[2] == 0.125, "dead units over the records found: " .. table.concat(dead, " "))
assert(med == 2 and found == 3 and bad == 1, string.format("median_of: %s, runs %s, diverged %s", tostring(med),
                                                             tostring(found), tostring(bad)))

-- ---- sweep: shards, resume ----
local runs = {}
for i = 1, 7 do runs[i] = { id = "r" .. i, config = { i = i } } end
local trained = {}
local function train(group)
  local out = {}
  for k, r in ipairs(group) do
    trained[#trained + 1] = r.id
    out[k] = { value = r.config.i * 10 }
  end
  return out
end
local s1 = Sweep.new { dir = tmp .. "/sw", runs = runs, shard = { index = 1, count = 3 }, label = "t" }
local slice = s1:slice()
assert(#slice == 3 and slice[1].id == "r1" and slice[2].id == "r4" and slice[3].id == "r7", "round-robin shard 1/3")
s1:run { train = train, chunk = 2, score = function(r) return r.value end }
assert(#trained == 3, "shard 1 trains its 3 runs")
trained = {}
s1:run { train = train }
assert(#trained == 0, "a re-run skips finished runs")
local full = Sweep.new { dir = tmp .. "/sw", runs = runs, label = "t" }
assert(#full:records() == 3 and #full:pending() == 4, "records found in the folder")
full:run { train = train, group_key = function(r) return r.config.i % 2 end }
assert(#trained == 4, "the unsharded run trains only the missing 4")
assert(#full:records() == 7 and full:records()[5].result.value == 50, "all records, in sweep order")
-- A record with a negative error (tampered, or corrupt) is not a finished run: it trains again.
local path5 = full:file(runs[5])
local text5 = results.read_file(path5)
results.write_file(path5, text5:gsub('"value": 50', '"value": 50, "best_val_mse": -1'))
assert(#full:records() == 6 and #full:pending() == 1 and full:pending()[1].id == "r5", "a negative MSE is refused")
trained = {}
full:run { train = train }
assert(#trained == 1 and trained[1] == "r5" and #full:records() == 7, "and trained again")
-- A non-numeric error (a string, a table) or a result that is not a table is not a finished run
-- either: the sweep trains it again instead of stopping on a comparison, and says so once.
local real_stderr, said = io.stderr, { text = "" }
function said:write(...) for _, t in ipairs({ ... }) do self.text = self.text .. t end end
io.stderr = said
results.write_file(path5, text5:gsub('"value": 50', '"value": 50, "best_val_mse": "0.5"'))
local path6 = full:file(runs[6])
local text6 = results.read_file(path6)
results.write_file(path6, text6:gsub('"result": {[^}]*}', '"result": 7'))
trained = {}
local ok_run, run_err = pcall(full.run, full, { train = train, score = function(r) return r.best_val_mse end })
io.stderr = real_stderr
assert(ok_run, "a string best_val_mse stops the sweep: " .. tostring(run_err))
assert(#trained == 2 and #full:records() == 7, "both trained again: " .. table.concat(trained, " "))
local _, n5 = said.text:gsub('best_val_mse = "0.5" is a string, not a number', "")
local _, n6 = said.text:gsub("its result is a number, not a table", "")
assert(n5 == 1 and n6 == 1, "each file is reported once:\n" .. said.text)
-- A changed configuration is not a finished run.
runs[2].config = { i = 2, epochs = 3 }
local changed = Sweep.new { dir = tmp .. "/sw", runs = runs, label = "t" }
assert(#changed:pending() == 1 and changed:pending()[1].id == "r2", "a run with a new configuration runs again")
ok, err = pcall(Sweep.new, { dir = tmp .. "/sw2", runs = { { id = "a b" } } })
assert(not ok and err:find("ids must be"), "bad id: " .. tostring(err))

-- Ctrl-C during the first group: that group is written, the rest is left for the next run.
local ffi = require "ffi"
ffi.cdef "int getpid(void); int kill(int pid, int sig);"
local irun = {}
for i = 1, 6 do irun[i] = { id = "i" .. i, config = { i = i } } end
local isweep = Sweep.new { dir = tmp .. "/int", runs = irun, label = "t" }
local finished, interrupted = isweep:run { chunk = 2, train = function(group)
  ffi.C.kill(ffi.C.getpid(), 2)  -- SIGINT, as a terminal's Ctrl-C
  return train(group)
end }
assert(interrupted == true and finished == 2, "Ctrl-C keeps the group in flight and stops: " .. tostring(finished))
assert(#isweep:pending() == 4, "4 runs left for the next run")
-- Ctrl-C inside sn.train stops it part-way: runs flagged `interrupted` are not written, the sweep
-- stops, and the next run trains them again.
local psweep = Sweep.new { dir = tmp .. "/part", runs = irun, label = "t" }
local pfinished, pstopped = psweep:run { chunk = 2, train = function(group)
  local out = train(group)
  out[2].interrupted = { epoch = 3, step = 17 }
  return out
end }
assert(pstopped == true and pfinished == 1, "a run stopped part-way is not kept: " .. tostring(pfinished))
assert(#psweep:pending() == 5 and psweep:pending()[1].id == "i2", "the stopped run trains again")

-- ---- progress ----
local sink = { text = "" }
function sink:write(...) for _, s in ipairs({ ... }) do self.text = self.text .. s end end
function sink:flush() end
local pr = Progress.new { total = 10, label = "x", tty = false, every = 0, out = sink, already = 2 }
pr:update(4, "0.001 (L4 W6)")
assert(sink.text:find("x 4/10 runs  ETA %S+  elapsed %S+  best 0.001 %(L4 W6%)"), "progress line: " .. sink.text)
-- The ETA counts the training alone: 100 s of dataset and shader setup before the first tick do
-- not make 1 run in 10 s look like 1 run in 110 s; no ETA before 2% of the work is done.
local now = 0
local pe = Progress.new { total = 10, label = "e", tty = false, every = 0, out = sink, clock = function() return now end }
now = 100
pe:update(0.01)
assert(pe:text():find("ETA ?", 1, true), "no ETA from the first tick: " .. pe:text())
now = 100.5
pe:update(0.15)
assert(pe:text():find("ETA ?", 1, true), "no ETA before 2% of the work: " .. pe:text())
now = 110
pe:update(1.01)
assert(pe:text():find("ETA 1m30s", 1, true), "ETA from the training's rate (1 run per 10 s, 8.99 left): " .. pe:text())
-- A group in flight counts as work, not as runs finished (288/360 showed for a group 80% done,
-- and Ctrl-C kept 0 of them).
pe:update(4.5, nil, 2)
assert(pe:text():find("e 2/10 runs (45% done)", 1, true), "runs finished and work done apart: " .. pe:text())
-- The last line is printed when the runs have finished, not when the work in flight reaches the
-- end (a log ended "0/12 runs (100% done)" and never said 12/12).
sink.text = ""
local pf = Progress.new { total = 2, label = "f", tty = false, every = 1e9, out = sink }
pf:update(2, nil, 0)
pf:update(2)
assert(sink.text:find("f 2/2 runs", 1, true), "the final line: " .. sink.text)
sink.text = ""
local prt = Progress.new { total = 10, label = "x", tty = true, out = sink }
prt:update(5)
assert(sink.text:sub(1, 1) == "\r" and sink.text:find("%[##########%.%.%.%.%.%.%.%.%.%.%]"), "tty bar: " .. sink.text)

-- ---- plot ----
local png, dropped = plot.lines { path = tmp .. "/plots/c.png", title = "t", xlabel = "epoch", ylabel = "MSE", logy = true,
                                  series = { { name = "a", x = { 1, 2, 3 }, y = { 0.1, 0 / 0, 0.01 } } } }
assert(sn.fs.exists(png) == "file" and dropped == 1, "plot written, NaN dropped and counted")
local img = sn.image.load(png)
local w, h = img:size()
assert(w == 800 and h == 520, "plot size")
assert(results.read_file(tmp .. "/plots/c.csv") == "series,x,y,label\na,1,0.1,\na,3,0.01,\n", "plot data beside it")
-- The gnuplot script beside it draws it where it lies when run by hand (it drew c.png.tmp.png,
-- a name two processes plotting into one folder also shared); no temporary file stays.
os.remove(png)
assert(os.execute(("cd %q && gnuplot c.gp"):format(tmp .. "/plots")) == 0 and sn.fs.exists(png) == "file", "c.gp draws c.png")
for _, f in ipairs(sn.fs.list(tmp .. "/plots")) do assert(not f:find("tmp"), "a temporary file left: " .. f) end
-- The key never hides data: a red point near the top right corner, where an inside key sat, is
-- drawn beside the key's own red sample (two discs, not one).
local function red_pixels(path)
  local im = sn.image.load(path)
  local iw, ih = im:size()
  local n = 0
  for y = 1, ih do
    for x = 1, iw do
      local px = im:get(x, y)
      if px[1] > 0.9 and px[2] < 0.2 and px[3] < 0.2 then n = n + 1 end
    end
  end
  return n
end
local ks = {}
for k = 1, 4 do ks[k] = { name = "a long series name number " .. k, x = { 0, 1 }, y = { 1, 2 } } end
ks[5] = { name = "corner", x = { 9.6 }, y = { 9.6 }, style = "points", color = "#ff0000" }
local one = red_pixels(plot.lines { path = tmp .. "/plots/one.png", xrange = { 0, 10 }, yrange = { 0, 10 },
                                    series = { { name = "corner", x = { 20 }, y = { 20 }, style = "points", color = "#ff0000" } } })
local keyed = red_pixels(plot.lines { path = tmp .. "/plots/key.png", series = ks, xrange = { 0, 10 }, yrange = { 0, 10 } })
assert(one > 10 and keyed >= 2 * one - 2, string.format("the key hides the point under it: %d red pixels, one disc %d", keyed, one))
-- Titles, labels and names are plain text, not gnuplot's markup: "my_{}sweep^{}" drawn as
-- markup is "mysweep" (an empty subscript and superscript).
local function titled(t, name)
  return sn.image.load(plot.lines { path = tmp .. "/plots/" .. name .. ".png", title = t,
                                    series = { { name = "x", x = { 1, 2 }, y = { 1, 2 } } } })
end
assert(sn.image.mse(titled("mysweep", "t1"), titled("my_{}sweep^{}", "t2")) > 0, "gnuplot markup in a title is drawn as text")

os.execute("rm -rf '" .. tmp .. "'")
print("scripts lib: ok")

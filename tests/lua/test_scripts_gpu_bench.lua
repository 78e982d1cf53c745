-- tools/gpu_bench.sh --quick: every step runs and leaves its log, the results and a summary, all
-- packed into OUTDIR.tar.gz; a failing step is recorded and the next ones still run; plots left
-- for later (SHADENET_PLOTS=later, a machine without gnuplot) are drawn by tools/draw_plots.sh.
-- (Its ctest step is left out here: a ctest inside this ctest run would share Testing/.)
local sn = require "shadenet"
local C = require "script_check"
local results = require "lib.results"

local sh = C.sh
local function read(path) return assert(results.read_file(path), path .. " is missing") end

local base = C.tmpdir("gpu_bench")

-- A quick run: every step ok.
local dir = base .. "/run"
local ok = sh(("SHADENET_PLOTS=later tools/gpu_bench.sh --quick --skip ctest %s > %s.out 2>&1"):format(dir, dir))
local summary = read(dir .. "/summary.txt")
assert(ok, "gpu_bench.sh --quick failed:\n" .. read(dir .. ".out"))
for _, s in ipairs { "machine", "gl_info", "train", "train_per_net", "render", "tables_4_5_4_7", "table_4_1" } do
  assert(summary:match("\n" .. s .. " +ok +[%d.]+ s  %(limit %d+ s%)  " .. s .. "%.log"), s .. " not ok:\n" .. summary)
end
assert(summary:match("\nctest +skipped"), summary)
assert(summary:match("\nsteps failed: 0\n") and summary:match("\nplots: left as gnuplot scripts"), summary)
local gl = read(dir .. "/gl_info.log")
assert(gl:match("\nplatform: %a+ %(EGL%)\n") and gl:match("SHADENET_EGL_PLATFORM=device:\nshadenet [%d.]+ %(build [^)\n]+%)\nplatform: device %(EGL%)\n"), gl)
local train = read(dir .. "/train.log")
assert(train:match("\ngl +4x6 +tanh +none +6 +1 +%d+") and train:match("\ngl +4x6 +tanh +none +6 +2 +%d+"), train)
local per_net = read(dir .. "/train_per_net.log")
assert(per_net:match("\ngl +4x6 +tanh +none +6 +2 +%d+") and per_net:find("\ngl kernel: per_net (SHADENET_GL_KERNEL)\n", 1, true), per_net)
assert(read(dir .. "/render.log"):match("Table 4%.6 .*\n4x4 +[%d.]+ | %- +[%d.]+ | %-\n"), read(dir .. "/render.log"))
assert(#C.csv(dir .. "/results/tables_4_5_4_7_performance/table_render.csv") == 2 * 4, "two sizes x four networks")
assert(read(dir .. "/results/table_4_1_phong/run.json"):find('"quick": true', 1, true))
local plots = dir .. "/results/tables_4_5_4_7_performance/plots/"
assert(sh("test -s " .. plots .. "render_time.gp") and not sh("test -e " .. plots .. "render_time.png"), "plot left for later")
assert(sh("tools/draw_plots.sh " .. dir .. "/results > /dev/null"), "tools/draw_plots.sh failed")
local drawn = sn.image.load(plots .. "render_time.png")
assert(select(1, drawn:size()) == 1000, "the plot as the script asked for it (1000 pixels wide)")
local listing = io.popen("tar -tzf " .. dir .. ".tar.gz"):read("*a")
for _, f in ipairs { "run/summary.txt", "run/train.log", "run/results/tables_4_5_4_7_performance/run.json",
                     "run/results/table_4_1_phong/table.md" } do
  assert(listing:find("\n" .. f .. "\n", 1, true) or listing:find("^" .. f .. "\n"), f .. " not packed:\n" .. listing)
end

-- A broken step (no EGL platform of that name) fails alone; the others run, the tarball is written.
local bad = base .. "/bad"
ok = sh(("SHADENET_EGL_PLATFORM=gpu tools/gpu_bench.sh --quick --skip train,train_per_net,render,ctest %s > %s.out 2>&1"):format(bad, bad))
assert(not ok, "gpu_bench.sh should fail when a step fails")
summary = read(bad .. "/summary.txt")
assert(summary:match("\nmachine +ok"), summary)
for _, s in ipairs { "gl_info", "tables_4_5_4_7", "table_4_1" } do
  assert(summary:match("\n" .. s .. " +failed %(exit 1%)"), s .. ":\n" .. summary)
end
assert(summary:match("\nsteps failed: 3\n"), summary)
assert(read(bad .. "/gl_info.log"):find("SHADENET_EGL_PLATFORM='gpu': unknown EGL platform", 1, true))
assert(sh("test -s " .. bad .. ".tar.gz"))
sh("rm -rf '" .. base .. "'")
print("ok")

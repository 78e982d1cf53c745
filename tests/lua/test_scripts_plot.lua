-- lib.plot's files: a plot's path never reaches the shell or gnuplot as code (a folder named
-- "$(touch ...)", one starting with "-", quotes and backquotes in names and titles); a failing
-- gnuplot's error carries its output and leaves the old PNG, CSV and .gp and no temporary; the
-- .gp draws the plot again by hand in its folder, and tools/draw_plots.sh draws a plot left for
-- later there; a series with no point says so in the key. The full disk: test_full_disk.lua.
package.path = "scripts/?.lua;" .. package.path
local sn = require "shadenet"
local check = require "script_check"
local results = require "lib.results"
local plot = require "lib.plot"

local tmp = sn.fs.tempdir("test_scripts_plot")
local read = results.read_file
local function sh_quote(s) return "'" .. tostring(s):gsub("'", "'\\''") .. "'" end
local function listing(dir) return table.concat(sn.fs.list(dir), " | ") end

-- ---- hostile names ----
-- A command that ran would touch $SN_PWNED1..5 (a path through the environment: a name holds no "/").
local pwned = tmp .. "/PWNED"
local ffi = require "ffi"
ffi.cdef "int setenv(const char* name, const char* value, int overwrite);"
ffi.C.setenv("SN_PWNED", pwned, 1)
local dir = tmp .. "/$(touch ${SN_PWNED}1)/-d/it's \"here\""
local name = "a'b `touch ${SN_PWNED}2` $(touch ${SN_PWNED}3)"
local path = dir .. "/" .. name .. ".png"
local series = { { name = "it's `touch ${SN_PWNED}4`", x = { 1, 2, 3 }, y = { 1, 3, 2 } } }
local png = plot.lines { path = path, title = "`touch ${SN_PWNED}5` it's", xlabel = "x @out", series = series }
assert(png == path, tostring(png))
for i = 1, 5 do assert(not sn.fs.exists(pwned .. i), "a name ran as a command: " .. pwned .. i) end
local w, h = sn.image.load(path):size()
assert(w == 800 and h == 520, "the plot is drawn")
assert(listing(dir) == name .. ".csv | " .. name .. ".gp | " .. name .. ".png", "only the plot's files: " .. listing(dir))
assert(read(dir .. "/" .. name .. ".csv") == "series,x,y,label\n" .. series[1].name .. ",1,1,\n" .. series[1].name .. ",2,3,\n"
       .. series[1].name .. ",3,2,\n", read(dir .. "/" .. name .. ".csv"))
-- Run by hand in its folder, the .gp draws the same picture over NAME.png, running nothing.
local first = sn.image.load(path)
os.remove(path)
assert(check.sh("cd -- " .. sh_quote(dir) .. " && gnuplot " .. sh_quote(name .. ".gp") .. " 2>/dev/null"), "the .gp runs")
assert(sn.image.mse(first, sn.image.load(path)) == 0, "the .gp draws the same plot")
for i = 1, 5 do assert(not sn.fs.exists(pwned .. i), "the .gp ran a command: " .. pwned .. i) end

-- ---- a failing gnuplot ----
-- The error names the plot and carries gnuplot's own words; the old PNG, CSV and .gp stay as they
-- were (they are one generation) and no temporary is left beside them.
local before = { read(path), read(dir .. "/" .. name .. ".csv"), read(dir .. "/" .. name .. ".gp") }
local ok, err = pcall(plot.lines, { path = path, key = "nonsense_word", series = { { name = "new", x = { 1 }, y = { 5 } } } })
assert(not ok and err:find("cannot draw " .. path .. ": gnuplot failed (exit status 1):", 1, true) and
       err:find("nonsense_word", 1, true), tostring(err))
assert(read(path) == before[1] and read(dir .. "/" .. name .. ".csv") == before[2] and read(dir .. "/" .. name .. ".gp") == before[3],
       "a failed plot changed the old files")
assert(listing(dir) == name .. ".csv | " .. name .. ".gp | " .. name .. ".png", "files left: " .. listing(dir))

-- Without gnuplot the error says what the shell said and how to go on.
local child = check.child("nognuplot", ([[
package.path = "scripts/?.lua;" .. package.path
require "lib.plot".lines { path = %q, series = { { name = "a", x = { 1 }, y = { 1 } } } }
]]):format(tmp .. "/nognuplot/p.png"))
local code, out = check.run(child, {}, { PATH = "/nonexistent" })
assert(code == 1 and out:find("cannot draw " .. tmp .. "/nognuplot/p.png: gnuplot failed (exit status 127):", 1, true)
       and out:find("gnuplot: not found", 1, true) and out:find("SHADENET_PLOTS=later", 1, true), out)
assert(not sn.fs.exists(tmp .. "/nognuplot"), "nothing written: " .. out)

-- ---- a series with no point to draw ----
-- It keeps its key entry, which says why no line is there (fig. 4.11's diverged "exponential"
-- had a key entry and no line, as if hidden under another); a plot with no point at all is an
-- empty frame with its key, not gnuplot's "x range is invalid".
local _, dropped = plot.lines { path = tmp .. "/empty/e.png", logy = true, series = {
  { name = "fine", x = { 1, 2 }, y = { 1, 2 } }, { name = "diverged", x = { 1, 2 }, y = { 0 / 0, math.huge } },
  { name = "at zero", x = { 1, 2 }, y = { 0, -1 } } } }
local gp = read(tmp .. "/empty/e.gp")
assert(dropped == 4 and gp:find("title 'fine',", 1, true) and gp:find("title 'diverged (no finite values)',", 1, true) and
       gp:find("title 'at zero (no positive values)'\n", 1, true), gp)
assert(read(tmp .. "/empty/e.csv") == "series,x,y,label\nfine,1,1,\nfine,2,2,\n", read(tmp .. "/empty/e.csv"))
_, dropped = plot.lines { path = tmp .. "/empty/all.png", logy = true,
                          series = { { name = "diverged", x = { 1, 2 }, y = { 0 / 0, 0 / 0 } } } }
w, h = sn.image.load(tmp .. "/empty/all.png"):size()
assert(dropped == 2 and w == 800 and h == 520, "a plot of nothing is drawn")
gp = read(tmp .. "/empty/all.gp")  -- gnuplot leaves a data file without rows out of the key
assert(gp:find("plot keyentry with lines lw 2 title 'diverged (no finite values)'", 1, true), gp)

-- ---- left for later, drawn by tools/draw_plots.sh ----
local later_dir = tmp .. "/later/-x/it's"
child = check.child("later", ([[
package.path = "scripts/?.lua;" .. package.path
print((require "lib.plot".lines { path = %q, series = { { name = "a", x = { 1, 2 }, y = { 1, 2 } } } }))
]]):format(later_dir .. "/it's.png"))
out = check.ok(child, {}, { SHADENET_PLOTS = "later" })
assert(out == later_dir .. "/it's.gp\n" and listing(later_dir) == "it's.csv | it's.gp", out .. listing(later_dir))
out = check.output("tools/draw_plots.sh " .. sh_quote(tmp .. "/later"))
assert(out:find("1 plot(s) drawn", 1, true), out)
w, h = sn.image.load(later_dir .. "/it's.png"):size()
assert(w == 800 and h == 520 and listing(later_dir) == "it's.csv | it's.gp | it's.png", listing(later_dir))
-- A script gnuplot fails on: its words in the error, nothing left beside it (a 0-byte temporary was).
results.write_file(tmp .. "/later2/b.gp", "set terminal pngcairo\nset output out\nnonsense_command\n")
out = check.output("{ tools/draw_plots.sh " .. sh_quote(tmp .. "/later2") .. "; echo exit $?; }")
assert(out:find("draw_plots.sh: gnuplot failed on " .. tmp .. "/later2/b.gp:", 1, true) and out:find("nonsense_command", 1, true)
       and out:find("exit 1\n$"), out)
assert(listing(tmp .. "/later2") == "b.gp", "files left: " .. listing(tmp .. "/later2"))

print("plot files: ok")

-- lib.plot's files: a plot's path never reaches the shell or gnuplot as code (a folder named
-- "$(touch ...)", one starting with "-", quotes and backquotes in names and titles); a failing
-- gnuplot's error carries its output and leaves the old PNG, CSV and .gp and no temporary; the
-- .gp draws the plot again by hand in its folder. The full disk: tests/lua/test_full_disk.lua.
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

print("plot files: ok")

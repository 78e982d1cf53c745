-- sn.fs.tempdir: fresh folders under TMPDIR, each its own, removed with their contents when the
-- script ends, normally or by an error; a bad tag or TMPDIR is an error naming the line.
local sn = require "shadenet"
local check = require "script_check"

local a, b = sn.fs.tempdir(), sn.fs.tempdir("probe")
assert(a ~= b and sn.fs.exists(a) == "folder" and #sn.fs.list(a) == 0, "two fresh, empty folders")
assert(a:match("/shadenet%-script%-[%w]+$") and b:match("/shadenet%-probe%-[%w]+$"), a .. " " .. b)
collectgarbage() collectgarbage()
assert(sn.fs.exists(b) == "folder", "a collection keeps the folder")

-- A child makes a folder under our TMPDIR, fills it, prints its path and ends as `how` says.
local root = sn.fs.tempdir("root")
for _, how in ipairs { "return", "error" } do
  local script = check.child("child", ([[
local sn = require "shadenet"
local d = sn.fs.tempdir("child")
sn.fs.mkdir(d .. "/sub/deeper")
sn.fs.write(d .. "/sub/deeper/f.txt", "x")
print("made " .. d)
if %q == "error" then error("the script fails", 0) end
]]):format(how))
  local code, out = check.run(script, {}, { TMPDIR = root })
  local made = out:match("made (%S+)")
  assert(made and made:sub(1, #root + 1) == root .. "/", "the child's folder is under TMPDIR: " .. out)
  assert(code == (how == "error" and 1 or 0), how .. ": exit " .. tostring(code) .. "\n" .. out)
  assert(sn.fs.exists(made) == nil, how .. ": " .. made .. " was left behind")
end
assert(#sn.fs.list(root) == 0, "nothing left under TMPDIR")

local code, out = check.run((check.child("bad", 'local sn = require "shadenet"\nlocal d = sn.fs.tempdir("a/b")\n')))
assert(code == 1 and out:find("child.lua:2: a scratch folder's tag must be a non%-empty name without '/', got 'a/b'"),
       out)
code, out = check.run((check.child("tmp", 'local sn = require "shadenet"\nsn.fs.tempdir()\n')), {},
                      { TMPDIR = root .. "/missing" })
assert(code == 1 and out:find("child.lua:2: cannot make a scratch folder .*/missing/shadenet%-script%-%w+: No such file"),
       out)
-- Folders a killed process left (a plot's, after Ctrl-C while gnuplot drew) are removed by the
-- next folder of their tag once they are a minute old and no process holds them; a younger one,
-- another tag's, and one a live process holds stay. (They piled up in TMPDIR.)
local T = sn.fs.tempdir("abandoned")
local stale, young, other = T .. "/shadenet-plot-abc123", T .. "/shadenet-plot-young1", T .. "/shadenet-probe-abc123"
local holder = check.child("holder", [[
local sn = require "shadenet"
local d = sn.fs.tempdir("plot")
sn.fs.write(d .. "/plot.png", "x")
io.stdout:write(d, "\n") io.stdout:flush()
-- Until the test says go, or its folder is gone (the test failed).
while not sn.fs.exists(os.getenv("GO")) and sn.fs.exists(os.getenv("GO"):match("^(.*)/")) do os.execute("sleep 0.05") end
]])
check.sh(string.format("GO=%s/go TMPDIR=%s %s %s > %s/held.txt 2>&1 &", T, T, check.shadenet, holder, T))
local held
for _ = 1, 400 do
  held = (sn.fs.exists(T .. "/held.txt") and sn.fs.read(T .. "/held.txt") or ""):match("(%S+shadenet%-plot%-%w+)")
  if held then break end
  os.execute("sleep 0.05")
end
assert(held, "the holder made its folder")
for _, d in ipairs { stale, young, other } do sn.fs.write(d .. "/plot.png", "left by a killed plot") end
os.execute(string.format("touch -d '2 minutes ago' '%s' '%s' '%s'", stale, other, held))
code, out = check.run((check.child("next", 'local sn = require "shadenet"\nprint(sn.fs.tempdir("plot"))\n')), {},
                      { TMPDIR = T })
assert(code == 0, out)
assert(sn.fs.exists(stale) == nil, "the abandoned folder is removed")
assert(sn.fs.exists(young) and sn.fs.exists(other) and sn.fs.exists(held), "the others stay")
sn.fs.write(T .. "/go", "")
for _ = 1, 400 do
  if not sn.fs.exists(held) then break end
  os.execute("sleep 0.05")
end
assert(sn.fs.exists(held) == nil, "the holder removed its own folder")
print("tempdir ok")

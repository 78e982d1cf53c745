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
print("tempdir ok")

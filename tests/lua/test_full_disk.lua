-- Nothing lost on a full disk: on a 64 KiB tmpfs, writers that run out of space leave the old
-- file as it was, no temporary behind, and an error naming the path and the cause. Needs root to
-- mount the tmpfs; elsewhere it says so and checks nothing.
local sn = require "shadenet"
package.path = "scripts/?.lua;" .. package.path
local results = require "lib.results"

local dir = "/tmp/shadenet_full_disk_" .. tostring(os.time()) .. "_" .. tostring(math.random(1, 1e6))
os.execute(("mkdir -p %q"):format(dir))
local mounted = os.execute(("mount -t tmpfs -o size=64k tmpfs %q 2>/dev/null"):format(dir))
if not (mounted == 0 or mounted == true) then
  os.execute(("rmdir %q"):format(dir))
  print("SKIPPED: cannot mount a tmpfs here (not root?)")
  return
end
local function cleanup() os.execute(("umount %q; rmdir %q"):format(dir, dir)) end

local ok, err = pcall(function()
  local function read(path)
    local f = assert(io.open(path, "rb"))
    local s = f:read("*a")
    f:close()
    return s
  end
  local function only(names)
    local list = sn.fs.list(dir)
    assert(#list == #names, "files left: " .. table.concat(list, ", "))
  end
  local big = string.rep("x", 200 * 1024)

  -- results.write_file (tables, CSV, JSON of every script) and sn.fs.write.
  results.write_file(dir .. "/table.md", "old table\n")
  local ok1, e1 = pcall(results.write_file, dir .. "/table.md", big)
  assert(not ok1 and tostring(e1):find("No space left on device", 1, true) and tostring(e1):find("table.md", 1, true), tostring(e1))
  assert(read(dir .. "/table.md") == "old table\n", "the old table survives")
  only { "table.md" }

  -- Images (PNG and EXR).
  local small = sn.image.new { width = 4, height = 4, channels = 4, fill = 0.5 }
  small:save(dir .. "/a.png")
  small:save(dir .. "/b.exr")
  local before_png, before_exr = read(dir .. "/a.png"), read(dir .. "/b.exr")
  local noise = sn.image.new { width = 256, height = 256, channels = 4, fill = 0 }
  for y = 1, 256 do for x = 1, 256 do noise:set(x, y, { math.random(), math.random(), math.random(), 1 }) end end
  for _, name in ipairs { "a.png", "b.exr" } do
    local okn, en = pcall(function() noise:save(dir .. "/" .. name) end)
    assert(not okn and tostring(en):find(name, 1, true), name .. ": " .. tostring(en))
  end
  assert(read(dir .. "/a.png") == before_png and read(dir .. "/b.exr") == before_exr, "old images survive")
  only { "a.png", "b.exr", "table.md" }

  -- Many files flushed together (sn.fs.write_all, run records): the one that does not fit fails
  -- the call before any is renamed, so both old files survive and no temporary is left.
  results.write_jsons { [dir .. "/r1.json"] = { run = 1 }, [dir .. "/r2.json"] = { run = 2 } }
  local old1, old2 = read(dir .. "/r1.json"), read(dir .. "/r2.json")
  assert(old1:find('"run": 1', 1, true) and old2:find('"run": 2', 1, true), old1 .. old2)
  local okr, er = pcall(results.write_jsons, { [dir .. "/r1.json"] = { run = "new" }, [dir .. "/r2.json"] = { big = big } })
  assert(not okr and tostring(er):find("No space left on device", 1, true) and tostring(er):find("r2.json", 1, true), tostring(er))
  assert(read(dir .. "/r1.json") == old1 and read(dir .. "/r2.json") == old2, "the old records survive")
  only { "a.png", "b.exr", "r1.json", "r2.json", "table.md" }
  local oka, ea = pcall(sn.fs.write_all, { [dir .. "/x"] = 1 })
  assert(not oka and tostring(ea):find("path = content (strings), got string = number", 1, true), tostring(ea))

  -- A dataset export (a sidecar and two .npy arrays) that does not fit leaves the old export
  -- whole and loadable: the arrays and the sidecar replace the old ones only once all are written.
  os.remove(dir .. "/a.png"); os.remove(dir .. "/b.exr")
  local function rows(n)
    local x, y = {}, {}
    for i = 1, n do x[i], y[i] = { i, 0.5, -i }, { 0.25, i / n, 1 } end
    return sn.dataset { x = x, y = y, split = 1 }
  end
  rows(10):export(dir .. "/ds.json")
  local old = { read(dir .. "/ds.json"), read(dir .. "/ds.inputs.npy"), read(dir .. "/ds.targets.npy") }
  local oke, ee = pcall(function() rows(4000):export(dir .. "/ds.json") end)
  assert(not oke and tostring(ee):find("No space left on device", 1, true), tostring(ee))
  assert(read(dir .. "/ds.json") == old[1] and read(dir .. "/ds.inputs.npy") == old[2] and
         read(dir .. "/ds.targets.npy") == old[3], "the old export survives")
  assert(sn.dataset.load(dir .. "/ds.json"):counts() == 10, "and loads")
  only { "ds.inputs.npy", "ds.json", "ds.targets.npy", "r1.json", "r2.json", "table.md" }

  -- An experiment's table (Markdown + CSV) that does not fit leaves both old files: written one
  -- by one, the new Markdown had replaced the old beside the old CSV.
  for _, f in ipairs { "ds.inputs.npy", "ds.json", "ds.targets.npy", "r1.json", "r2.json", "table.md" } do
    os.remove(dir .. "/" .. f)
  end
  local R = results.open({ out = dir }, "full")
  local columns = { { key = "name", header = "Name" } }
  R:table { file = "t", columns = columns, rows = { { name = "old" } } }
  local old_md, old_csv = read(dir .. "/t.md"), read(dir .. "/t.csv")
  local long = {}
  for i = 1, 1400 do long[i] = { name = string.rep("n", 20) .. i } end
  local okt, et = pcall(R.table, R, { file = "t", columns = columns, rows = long })
  assert(not okt and tostring(et):find("No space left on device", 1, true), tostring(et))
  assert(read(dir .. "/t.md") == old_md and read(dir .. "/t.csv") == old_csv, "the old table survives, both files")
  only { "t.csv", "t.md" }

  -- A plot (lib.plot) that does not fit leaves its old PNG, CSV and .gp: gnuplot's cairo reported
  -- success on the full disk, and its PNG, cut short at 8192 bytes, replaced the good one.
  os.remove(dir .. "/t.md"); os.remove(dir .. "/t.csv")
  local plot = require "lib.plot"
  local xs, ys = {}, {}
  for i = 1, 40 do xs[i], ys[i] = i, math.sin(i) + 2 end
  local spec = { path = dir .. "/p.png", title = "a plot", series = { { name = "a", x = xs, y = ys, style = "linespoints" } } }
  plot.lines(spec)
  local old_plot = { read(dir .. "/p.png"), read(dir .. "/p.csv"), read(dir .. "/p.gp") }
  assert(#old_plot[1] > 16 * 1024, "a plot bigger than the free space left below: " .. #old_plot[1] .. " bytes")
  local function free()
    local p = io.popen(("df -B1 --output=avail %q | tail -1"):format(dir))
    local n = tonumber(p:read("*a"))
    p:close()
    return n
  end
  local fills = 0
  local function fill_to(bytes)  -- a new file each time: rewriting one needs room for two
    fills = fills + 1
    local f = assert(io.open(dir .. "/fill" .. fills, "wb"))
    assert(f:write(string.rep("f", free() - bytes)) and f:close())
  end
  fill_to(16 * 1024)
  local okp, ep = pcall(plot.lines, spec)
  assert(not okp and tostring(ep):find("No space left on device", 1, true) and tostring(ep):find(dir .. "/p.", 1, true), tostring(ep))
  assert(read(dir .. "/p.png") == old_plot[1] and read(dir .. "/p.csv") == old_plot[2] and read(dir .. "/p.gp") == old_plot[3],
         "the old plot survives, all three files")
  only { "fill1", "p.csv", "p.gp", "p.png" }

  -- gnuplot's own PNG cut short (its scratch folder, under TMPDIR, on the full disk) is refused
  -- before it reaches the plot's folder.
  sn.fs.mkdir(dir .. "/tmp")
  fill_to(12 * 1024)
  local check = require "script_check"
  local target = sn.fs.tempdir("full_disk_plot") .. "/q.png"
  spec.path = target
  plot.lines(spec)
  local old_q = read(target)
  local child = check.child("full_disk_plot", ([[
package.path = "scripts/?.lua;" .. package.path
local xs, ys = {}, {}
for i = 1, 40 do xs[i], ys[i] = i, math.sin(i) + 2 end
require "lib.plot".lines { path = %q, title = "a plot", series = { { name = "a", x = xs, y = ys, style = "linespoints" } } }
]]):format(target))
  local code, out = check.run(child, {}, { TMPDIR = dir .. "/tmp" })
  assert(code == 1 and out:find("cannot draw " .. target .. ": gnuplot's PNG in " .. dir .. "/tmp/shadenet-plot-", 1, true)
         and out:find("is not whole", 1, true), out)
  assert(read(target) == old_q, "the old plot survives")
  assert(#sn.fs.list(dir .. "/tmp") == 0, "the scratch folder is removed: " .. table.concat(sn.fs.list(dir .. "/tmp"), " "))

  -- Live mode's screenshot and recording on a full disk: an error naming the file, and no empty
  -- screenshot-NNNN.png or record-NNNN folder left claimed for them.
  for _, f in ipairs(sn.fs.list(dir)) do os.execute(("rm -rf %q"):format(dir .. "/" .. f)) end
  local filler = assert(io.open(dir .. "/filler", "wb"))
  filler:write(string.rep("f", 63000))
  filler:close()
  local script = dir .. "/../shadenet_full_disk_live.lua"
  sn.fs.write(script, [[
local sn = require "shadenet"
local scene = sn.scene { mesh = sn.mesh.sphere(), size = { 160, 120 }, light = { dir = { 0.5, 0.7, 0.6 } } }
sn.live.show { scene = scene, truth = sn.lighting.phong {}, mode = "truth" }
print(pcall(sn.live.screenshot))
print(pcall(sn.record, { orbit = { count = 2 } }))
]])
  local exe = arg[-1] or "build/shadenet"
  if exe:sub(1, 1) ~= "/" then exe = os.getenv("PWD") .. "/" .. exe end
  local p = io.popen(("cd %q && %q %q 2>&1"):format(dir, exe, script))
  local said = p:read("*a")
  p:close()
  os.remove(script)
  assert(said:find("false\tsn.live.screenshot: cannot write image 'out/live/screenshot-0001.png': No space left", 1, true) and
         said:find("false\tsn.record: cannot write image 'out/live/record-0001/frame-0001.png': No space left", 1, true), said)
  local left = sn.fs.list(dir .. "/out/live")
  assert(#left == 0, "left claimed: " .. table.concat(left, ", "))
end)
cleanup()
assert(ok, err)
print("ok")

-- Two live sessions in the same folder take screenshots and record at the same moment: every
-- file of both is kept (the numbers are claimed, not looked up, so neither overwrites the other).
local sn = require "shadenet"
package.path = "tests/live/?.lua;" .. package.path
local H = require "harness"

local dir = "out/live_tests/two_instances"
os.execute(("rm -rf %q && mkdir -p %q"):format(dir, dir))
H.write(dir .. "/tint.frag", H.read("tests/live/tint.frag"))
local script = dir .. "/s.lua"
H.write(script, ([[
local sn = require "shadenet"
local sphere = sn.mesh.sphere { segments = 24, rings = 12 }
local program = sn.program { vertex = "mesh.vert", fragment = %q }
sn.live.show {
  truth = function(view)
    local t = sn.target { width = view.width, height = view.height }
    sn.draw { target = t, program = program, mesh = sphere, camera = view.camera, clear = { 0, 0, 0, 0 },
              uniforms = { u_tint = { 0.8, 0.5, 0.3 }, u_light = view.light.dir } }
    return t
  end,
  camera = sn.camera { eye = { 0.6, 0.8, 2.6 } },
}
-- Taken as the script runs, before the loop's first frame: still at the loop's --size.
print("EARLY " .. sn.live.screenshot())
]]):format(dir .. "/tint.frag"))

local a = H.start { dir = dir .. "/a", script = script, window = false }
local b = H.start { dir = dir .. "/b", script = script, window = false }
a:wait_log("%[live%] ran")
b:wait_log("%[live%] ran")
for _, s in ipairs({ a, b }) do
  local early = s:wait_log("EARLY ([^\n]+%.png)")
  local w, h = sn.image.load(early):size()
  assert(w == 160 and h == 120, early .. ", taken before the first frame, is at the --size: " .. w .. "x" .. h)
end
local line = "for i = 1, 4 do print('SHOT ' .. sn.live.screenshot()) end " ..
             "print('RECORD ' .. sn.record { orbit = { count = 2 }, width = 32, height = 32 }) print('DONE')"
a:send(line)
b:send(line)
local files = {}
for _, s in ipairs({ a, b }) do
  s:wait_log("DONE")
  for p in s:log():gmatch("SHOT ([^\n]+)") do files[#files + 1] = p end
  for p in s:log():gmatch("RECORD ([^\n]+)") do files[#files + 1] = p end
end
assert(#files == 10, "10 outputs printed, got " .. #files)
local seen = {}
for _, p in ipairs(files) do
  assert(not seen[p], "two instances wrote the same file: " .. p)
  seen[p] = true
end
for _, p in ipairs(files) do
  if p:find("%.png$") then
    local w, h = sn.image.load(p):size()
    assert(w == 160 and h == 120, p .. " is a whole screenshot at the --size given (headless): " .. w .. "x" .. h)
  else
    assert(sn.fs.exists(p .. "/frame-0002.png") == "file", p .. " holds its recording")
  end
end
a:stop()
b:stop()
print("two instances: 8 screenshots and 2 recordings, every name different, every file whole")

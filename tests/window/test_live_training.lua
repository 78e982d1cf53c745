-- Training inside a live session never freezes the window: while sn.train runs (the first run,
-- and a retrain after a reload) the window shows the last good picture with a progress bar, and
-- Esc cancels the training (the last good state stays). The rate (10 pictures a second or more,
-- issue 14) is measured and printed here and recorded in docs/performance.md; the test asserts
-- that pictures keep coming within one epoch, at a third of that rate, which a window frozen for
-- the epoch (one picture at most) fails and a machine shared with other tests still meets (a
-- fresh-clone CI run under ctest -j2 gave 8.2 a second).
local sn = require "shadenet"
package.path = "tests/live/?.lua;" .. package.path
local H = require "harness"

local dir = "out/live_tests/training"
os.execute(("rm -rf %q && mkdir -p %q"):format(dir, dir))
H.write(dir .. "/tint.frag", H.read("tests/live/tint.frag"))
local script = dir .. "/train.lua"
-- Version v trains a 64x64x64 network for `epochs` epochs of `rows` sampled rows (one epoch of
-- 1.6 million training rows is 200,000 steps, over a second here): the window must keep
-- drawing within an epoch, not only between epochs.
local function version(v, epochs, rows)
  return ([[
local sn = require "shadenet"
local net = sn.keep("net", function()
  local data = sn.dataset.sample { target = sn.lighting.phong {}, n = %d, seed = %d }
  local n = sn.mlp { inputs = 6, hidden = { 64, 64, 64 }, outputs = 3, seed = %d }
  io.stderr:write("TRAIN START %d\n")
  local t0 = sn.clock()
  sn.train { nets = n, data = data, epochs = %d, batch = 8, backend = "cpu" }
  io.stderr:write(("TRAINED %d in %%.3f s\n"):format(sn.clock() - t0))
  return n
end, { v = %d })
]]):format(rows, v, v + 1, v, epochs, v, v) .. ([[
local sphere = sn.mesh.sphere { segments = 24, rings = 12 }
local program = sn.program { vertex = "mesh.vert", fragment = %q }
local w = net.layers[1].weight
sn.live.show {
  network = function(view)
    local t = sn.target { width = view.width, height = view.height }
    sn.draw { target = t, program = program, mesh = sphere, camera = view.camera, clear = { 0, 0, 0, 1 },
              uniforms = { u_tint = { 0.6 + w[1][1], 0.6, 0.6 }, u_light = view.light.dir } }
    return t
  end,
  camera = sn.camera { eye = { 0.6, 0.8, 2.6 } },
}
]]):format(dir .. "/tint.frag")
end

local shown_dir = dir .. "/session/shown"
local function shown_count()
  local n = 0
  while H.exists(("%s/shown-%d.exr"):format(shown_dir, n + 1)) do n = n + 1 end
  return n
end

H.write(script, version(1, 1, 2000000))
local s = H.start { dir = dir .. "/session", script = script, size = "200x150", shown = true, limit = 60 }
s:wait_log("TRAIN START 1")
local before = shown_count()
local secs = tonumber(s:wait_log("TRAINED 1 in (%S+) s", 40))
local during = shown_count() - before
assert(secs > 1, "the training is long enough to measure (" .. secs .. " s)")
assert(during / secs >= 10 / 3, ("%d pictures in %.2f s of training: the window froze"):format(during, secs))
-- A picture from the middle of the training: the progress bar across the top, text on it.
local mid = sn.image.load(("%s/shown-%d.exr"):format(shown_dir, before + math.floor(during / 2)))
local p = mid:get(2, 2)
assert(p[3] > 0.6 and p[3] > 2 * p[1], ("the bar's filled part at the top left: %g %g %g"):format(p[1], p[2], p[3]))
s:wait_frame(1)
local good = s:image(1)
print(("1. first training: %d pictures in %.2f s (%.1f a second), progress bar drawn"):format(during, secs, during / secs))

-- 2. A reload that retrains: the last good picture stays under the bar.
local n0 = shown_count()
H.write(script, version(2, 1, 2000000))
s:wait_log("TRAIN START 2")
local n1, pic = s:wait_shown(n0 + 2)
local w, h = pic:size()
local a, b = pic:get(math.floor(w / 2), math.floor(h / 2)), good:get(math.floor(w / 2), math.floor(h / 2))
for c = 1, 3 do assert(a[c] == b[c], "the last good picture is shown while retraining") end
s:wait_log("TRAINED 2 in")
print("2. retraining after a reload showed the last good picture under the bar")

-- 3. Esc cancels a training: the session goes on with the last good network.
H.write(script, version(3, 3, 2000000))
s:wait_log("TRAIN START 3")
s:wait_shown(shown_count() + 1)
local x = H.x11()
x:move(100, 75)
x:key("Escape")
x:close()
s:wait_log("%[live%] cancelled: training")
s:wait_log("%[live%] error: [^\n]*train.lua:%d+: sn.train: cancelled by the user %(Esc%) in epoch 1 of 3")
assert(not s:log():find("TRAINED 3", 1, true), "the training stopped")
s:send("print('ALIVE ' .. sn.live.frames())")
s:wait_log("ALIVE %d+")
s:stop()
print("3. Esc cancelled the training; the session kept its last good network")

-- 4. Closing the window during a training ends the session: the training stops and says why,
-- and the error that stops the run is not reported as one (it read "cancelled by the user (Esc)",
-- with a traceback).
H.write(script, version(4, 3, 2000000))
local s4 = H.start { dir = dir .. "/closing", script = script, size = "200x150", limit = 60 }
s4:wait_log("TRAIN START 4")
H.sleep(0.5)
local x4 = H.x11()
x4:close_window()
x4:close()
s4:wait_log("%[live%] window closed: training")
for _ = 1, 200 do
  if not H.exists(("/proc/%d/stat"):format(s4.pid)) then break end
  H.sleep(0.05)
end
s4.pipe:close()
local log4 = s4:log()
assert(not H.exists(("/proc/%d/stat"):format(s4.pid)), "the session ended")
assert(not log4:find("[live] error:", 1, true) and not log4:find("cancelled by the user", 1, true)
       and not log4:find("TRAINED 4", 1, true),
       "closed, not cancelled with an error:\n" .. log4)
print("4. closing the window stopped the training and ended the session without an error report")

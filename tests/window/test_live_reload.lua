-- Live reload keeps state: saving a new version of the watched script that edits a weight shows
-- the edit in the very next frame, within a bounded time, without training again; the new frame
-- equals the headless render of that version; deleting the edit brings the trained weights back.
-- The scene is a trained network rendered by scene:render (net:render), as in the example.
local sn = require "shadenet"
package.path = "tests/live/?.lua;" .. package.path
local H = require "harness"

local dir = "out/live_tests/reload"
os.execute(("mkdir -p %q"):format(dir))
local template = H.read("tests/live/scene_scenario.lua")
local script = dir .. "/scenario.lua"
H.write(script, template)

local s = H.start { dir = dir, script = script }
s:wait_frame(1)
local trained = tonumber(s:wait_log("TRAINED (%d+)"))
assert(trained > 0, "the network trained")
local v1 = s:image(1)

-- Version 2 raises the output layer's red bias by 0.25. The edit must show in the frame that
-- follows the save: red up by 0.25 on every covered pixel (the output layer is linear), green
-- and blue untouched.
local edit = "net.layers[3].bias[1] = net.layers[3].bias[1] + 0.25\n"
local t_save = sn.clock()
H.write(script, (template:gsub("%-%- EDITS\n", edit)))
local waited = s:wait_frame(2, 15)
local v2 = s:image(2)
print(("weight edit visible %.0f ms after the save (frame 2)"):format((sn.clock() - t_save) * 1e3))
assert(waited < 10, "the edit took too long to show")
local w, h = v1:size()
local covered = 0
for y = 1, h do
  for x = 1, w do
    local a, b = v1:get(x, y), v2:get(x, y)
    if a[4] > 0.5 then
      covered = covered + 1
      assert(math.abs(b[1] - a[1] - 0.25) < 1e-4, ("pixel (%d,%d): red %g -> %g"):format(x, y, a[1], b[1]))
      assert(b[2] == a[2] and b[3] == a[3], ("pixel (%d,%d): green or blue changed"):format(x, y))
    end
  end
end
assert(covered > 1000, "the sphere covers the frame: " .. covered)

-- Not retrained: one TRAINED line, and the step counter is what training left.
s:send('print("STEPS " .. net:trained_steps())')
local steps = s:wait_log("STEPS (%d+)")
assert(tonumber(steps) == trained, ("trained_steps %s after the reload, %d after training"):format(steps, trained))
local _, count = s:log():gsub("TRAINED", "")
assert(count == 1, "the network trained " .. count .. " times")

-- The frame the window showed is the headless render of version 2 (same view, same pixels).
s:send(('print("VIEW " .. sn.live.view_code(%q))'):format(dir .. "/headless_v2.exr"))
local code = s:wait_log("VIEW ([^\n]+)")
local headless = dir .. "/headless.lua"
H.write(headless, ("local sn = require 'shadenet'\ndofile(%q)\n%s\nprint('HEADLESS OK')\n"):format(script, code))
H.run_headless(headless, "HEADLESS OK")
assert(H.same(v2, sn.image.load(dir .. "/headless_v2.exr")), "the window's frame differs from the headless render")

-- Version 3 drops the edit: the kept network goes back to its trained weights, exactly.
local n = s:settle()
H.write(script, template)
s:wait_frame(n + 1, 15)
assert(H.same(s:image(n + 1), v1), "removing the edit did not restore the trained weights")

-- Saving the same bytes again is no reason to redraw.
H.write(script, template)
H.sleep(0.5)
assert(s:frames() == n + 1, "an unchanged save redrew")
s:stop()
print("live reload: edit shown, network kept (" .. trained .. " steps), headless equal, edit undone")

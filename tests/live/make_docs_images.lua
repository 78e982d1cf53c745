-- Makes docs/images/live_*.png from a real live session of examples/live_edit.lua, and prints
-- the figures docs/live-mode.md quotes (title, save-to-frame time, idle CPU):
--   xvfb-run -a build/shadenet --window tests/live/make_docs_images.lua
local sn = require "shadenet"
package.path = "tests/live/?.lua;" .. package.path
local H = require "harness"
local dir = "out/docs_live"
os.execute("mkdir -p " .. dir)
local example = H.read("examples/live_edit.lua")
local script = dir .. "/live_edit.lua"
H.write(script, example)
local s = H.start { dir = dir .. "/session", script = script, size = "480x480", limit = 300 }
s:wait_frame(1, 120)
local n = s:settle()
print("TITLE1 " .. tostring(H.window_title("toon3")))
s:send('print("SHOT " .. sn.live.screenshot("docs/images/live_network.png"))')
s:wait_log("SHOT ")
n = s:settle()  -- the side view's picture: tests/live/make_hud_images.lua
local function edit(from, to, shot)
  local t0 = sn.clock()
  H.write(script, (example:gsub(from, to, 1)))
  s:wait_frame(n + 1, 60)
  print(("EDIT %s shown after %.0f ms"):format(shot, (sn.clock() - t0) * 1e3))
  n = s:settle()
  s:send(('print("SHOT3 " .. sn.live.screenshot(%q))'):format("docs/images/" .. shot .. ".png"))
  s:wait_log("SHOT3 [^\n]*" .. shot)
  n = s:settle()
end
edit("%-%- L%[1%]%.weight%[2%]%[1%] = 2%.0 ", "L[1].weight[2][1] = 2.0    ", "live_edit_first")
print("TITLE2 " .. tostring(H.window_title("toon3")))
edit("%-%- L%[9%]%.bias%[2%] = L%[9%]%.bias%[2%] %+ 0%.3 ", "L[9].bias[2] = L[9].bias[2] + 0.3  ", "live_edit_last")
edit("%-%- L%[6%]%.bias%[4%] = %-1%.5 ", "L[6].bias[4] = -1.5   ", "live_edit_middle")
-- errors, for the docs' terminal excerpt
H.write(script, (example:gsub("%-%- L%[1%]%.weight%[2%]%[1%] = 2%.0", "L[1].weight[2][1] = = 2.0", 1)))
s:wait_log("%[live%] error: [^\n]*live_edit%.lua")
print("TITLE3 " .. tostring(H.window_title("ERROR")))
H.write(script, example)
s:wait_log("fixed")
n = s:settle()
-- a sweep of the first-layer weight
s:send([[local w = L[1].weight; local d, f = sn.record { sweep = { set = function(v) w[2][1] = v end, get = function() return w[2][1] end, from = -2, to = 2, count = 5 }, width = 160, height = 160, dir = "out/docs_live/sweep" }; print("SWEEP " .. #f)]])
s:wait_log("SWEEP 5")
s:send('print("STEPS " .. net:trained_steps())')
print(s:wait_log("(STEPS %d+)"))
-- idle CPU over 5 s with the real example
n = s:settle()
H.sleep(1)
local c0, t0 = s:cpu_seconds(), sn.clock()
H.sleep(5)
print(("IDLE %.3f s CPU over %.2f s, frames %d -> %d"):format(s:cpu_seconds() - c0, sn.clock() - t0, n, s:frames()))
s:stop()
local panels = {}
for k = 1, 5 do
  panels[k] = { image = sn.image.load(("out/docs_live/sweep/frame-%04d.png"):format(k)), caption = ("L[1].weight[2][1] = %g"):format(-2 + (k - 1)) }
end
sn.image.grid { panels = panels, columns = 5 }:save("docs/images/live_sweep.png")
print(s:log())

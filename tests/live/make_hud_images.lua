-- Makes docs/images/live_{side_labelled,error_overlay,progress}.png: what the window shows
-- (overlays included, SHADENET_LIVE_SHOWN) in a real live session of examples/live_edit.lua:
--   xvfb-run -a -s "-screen 0 1280x1024x24" build/shadenet --window tests/live/make_hud_images.lua
local sn = require "shadenet"
package.path = "tests/live/?.lua;" .. package.path
local H = require "harness"
local dir = "out/docs_hud"
os.execute("mkdir -p " .. dir)
local example = H.read("examples/live_edit.lua")
local script = dir .. "/live_edit.lua"
H.write(script, example)
local s = H.start { dir = dir .. "/session", script = script, size = "640x480", limit = 300, shown = true }
s:wait_frame(1, 120)
s:settle()
local function save_shown(path)
  local n = s:shown()
  local _, img = s:wait_shown(n - 1)
  img:save(path)
  print("saved " .. path)
end
s:send("sn.live.set_view{ mode = 'side' }")
s:settle()
save_shown("docs/images/live_side_labelled.png")
s:send("sn.live.set_view{ mode = 'network' }")
s:settle()
H.write(script, (example:gsub("%-%- L%[1%]%.weight%[2%]%[1%] = 2%.0", "L[1].weight[2][1] = = 2.0", 1)))
s:wait_log("%[live%] error: [^\n]*live_edit%.lua")
H.sleep(0.5)
save_shown("docs/images/live_error_overlay.png")
H.write(script, example)
s:wait_log("fixed")
s:settle()
-- A retrain: a key for sn.keep makes the next run train again (120 epochs: long enough to see).
local n0 = s:shown()
H.write(script, (example:gsub('end%)\n', 'end, { epochs = 120 })\n', 1):gsub("epochs = 20,", "epochs = 120,", 1)))
local _, img = s:wait_shown(n0 + 25, 60)  -- a few epochs in
img:save("docs/images/live_progress.png")
print("saved docs/images/live_progress.png")
s:stop()

-- The window's own controls, driven through X like a user's hands: number keys switch the view,
-- a left drag orbits the camera, a right drag moves the light (the truth follows), S saves a
-- screenshot and prints its absolute path; the title shows the network, its val MSE and the
-- frame time.
local sn = require "shadenet"
package.path = "tests/live/?.lua;" .. package.path
local H = require "harness"

local dir = "out/live_tests/input"
local script = H.scenario(dir, function(text)
  return (text:gsub('title = "live test",', 'title = "live test", val_mse = function() return net:best().val_mse end,'))
end)

local s = H.start { dir = dir, script = script, size = "200x150" }
s:wait_frame(1)
local title = H.window_title("live test")
assert(title, "no window titled 'live test'")
assert(title:find("live test · network · val MSE %d") and title:find("%d+%.%d ms$"),
       "the title shows the network, its val MSE and the frame time: " .. title)
local x11 = H.x11()
x11:move(100, 75)  -- over the window (top-left of the screen, no window manager)

local function after(action)
  local n = s:frames()
  action()
  s:wait_frame(n + 1, 10)
  H.sleep(0.2)  -- a drag's last motion events may bring a frame or two more
  return s:image(s:frames())
end

local network = s:image(1)
local truth = after(function() x11:key("2") end)
assert(not H.same(truth, network), "key 2 shows the truth")
assert(H.window_title("live test · truth"), "the title names the view")
local err = after(function() x11:key("3") end)
assert(not H.same(err, truth), "key 3 shows the error heatmap")
after(function() x11:key("2") end)

-- Right drag: the light moves, the truth follows.
local lit = after(function() x11:drag(3, 60, 75, 140, 60) end)
assert(not H.same(lit, truth), "dragging the light changed the truth")
-- Left drag: the camera orbits (the sphere's silhouette stays, its shading turns).
local orbited = after(function() x11:drag(1, 60, 75, 140, 75) end)
assert(not H.same(orbited, lit), "the orbit changed the view")

-- S: a screenshot of the view, its absolute path on the terminal.
x11:key("s")
local path = s:wait_log("%[live%] screenshot: (/[^\n]+%.png)")
assert(H.exists(path), "the screenshot exists: " .. path)
local shot = sn.image.load(path)
assert(sn.image.mse(shot, s:image(s:frames()), { channels = 3 }) < 1e-4, "the screenshot is the view shown")
os.remove(path)

-- R: an orbit recorded as 36 frames of the current view.
x11:key("r")
local count, rec = s:wait_log("%[live%] recorded (%d+) frames of an orbit in (/[^\n]+)")
assert(tonumber(count) == 36 and H.exists(rec .. "/frame-0036.png"), "36 orbit frames in " .. rec)
assert(sn.image.mse(sn.image.load(rec .. "/frame-0001.png"), sn.image.load(rec .. "/frame-0019.png")) > 1e-4,
       "the orbit's frames differ")
os.execute(("rm -r %q"):format(rec))

-- Esc closes the session.
x11:key("Escape")
s.pipe:close()
x11:close()
print("input: keys 2/3, light and orbit drags, screenshot " .. path .. ", title: " .. title)

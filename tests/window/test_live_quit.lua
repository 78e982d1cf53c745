-- Q asks before console edits are lost: with none it quits at once; after a console edit (a
-- line that changed something, not a query) it asks in the window and on the terminal, and a
-- second Q within 3 s quits; the question goes after 3 s; a reload drops the edits (the script
-- is the truth again), so Q quits at once. The window's close button does as Q (it quit at once,
-- edits or not). An Esc read just after a training ended (it came too late to cancel it) asks
-- before it quits (it quit, and the freshly trained network was gone). (Ctrl-D at the console:
-- tests/lua/test_live_console_tty.lua.)
local sn = require "shadenet"
package.path = "tests/live/?.lua;" .. package.path
local H = require "harness"

local dir = "out/live_tests/quit"
local script, template = H.scenario(dir)
local ASK = "press Q (or Esc) again to quit"
local ASK_PATTERN = (ASK:gsub("%p", "%%%0"))

local function alive(s)
  local f = io.open(("/proc/%d/stat"):format(s.pid))
  if not f then return false end
  local state = f:read("*a"):match("%) (%a)")
  f:close()
  return state ~= "Z"
end
local function wait_exit(s, what)
  for _ = 1, 200 do
    if not alive(s) then return end
    H.sleep(0.05)
  end
  s:fail(what)
end
local function asks(s) return select(2, s:log():gsub(ASK_PATTERN, "")) end

local x11 = H.x11()
-- 1. Only queries at the console: Q quits at once.
local s = H.start { dir = dir .. "/s1", script = script, size = "240x180" }
s:wait_frame(1)
s:send("net:trained_steps()")
s:wait_log("\n%d+\n")
x11:move(120, 90)
x11:key("q")
wait_exit(s, "Q with no console edit quits at once")
assert(asks(s) == 0, "nothing was asked")
s.pipe:close()

-- 2. A console edit: Q asks (the window shows the question over the middle), Q again quits.
s = H.start { dir = dir .. "/s2", script = script, size = "240x180", shown = true }
s:wait_frame(1)
s:send("net.layers[1].weight[1][2] = -0.4")
s:wait_frame(2)
local n0 = s:shown()
x11:move(120, 90)
x11:key("q")
s:wait_log(ASK_PATTERN)
H.sleep(0.3)
assert(alive(s), "the first Q after an edit does not quit")
local _, pic = s:wait_shown(n0)
local frame = s:image(s:frames())
local centre, yellow = 0, 0
for y = 80, 100 do
  for x = 10, 230, 2 do
    local p, q = pic:get(x, y), frame:get(x, y)
    if math.abs(p[1] - q[1]) + math.abs(p[2] - q[2]) + math.abs(p[3] - q[3]) > 0.05 then centre = centre + 1 end
    if p[1] > 0.9 and p[2] > 0.8 and p[3] < 0.7 then yellow = yellow + 1 end
  end
end
assert(centre > 300 and yellow > 20, ("the question is drawn over the middle: %d changed, %d text pixels"):format(centre, yellow))
-- After 3 s the question has gone: Q asks again; then Q within 3 s quits.
H.sleep(3.3)
x11:key("q")
for _ = 1, 100 do if asks(s) == 2 then break end H.sleep(0.05) end
assert(asks(s) == 2 and alive(s), "after 3 s a Q asks again")
-- A second Q within 3 s quits. (XTest key events have been seen to go missing under Xvfb: if
-- the window heard nothing in 1 s, no new question and still alive, press again, still well
-- within the 3 s.)
x11:key("q")
for _ = 1, 20 do if not alive(s) then break end H.sleep(0.05) end
if alive(s) and asks(s) == 2 then x11:key("q") end
wait_exit(s, "a second Q within 3 s quits")
assert(asks(s) == 2, "the second Q quit without asking again")
s.pipe:close()

-- 3. An edit, then a reload: the edit is gone with it, Q quits at once.
s = H.start { dir = dir .. "/s3", script = script, size = "240x180" }
s:wait_frame(1)
s:send("net.layers[1].weight[1][2] = -0.4")
s:wait_frame(2)
H.write(script, template .. "\n-- saved again\n")
for _ = 1, 400 do
  if select(2, s:log():gsub("%[live%] ran ", "")) >= 2 then break end
  H.sleep(0.05)
end
assert(select(2, s:log():gsub("%[live%] ran ", "")) >= 2, "the save reloaded the script")
x11:move(120, 90)
x11:key("q")
wait_exit(s, "Q after a reload quits at once")
assert(asks(s) == 0, "nothing was asked after the reload")
s.pipe:close()

-- 4. The close button: at once without edits; after an edit it asks, and a second close quits.
s = H.start { dir = dir .. "/s4", script = script, size = "240x180" }
s:wait_frame(1)
x11:close_window()
wait_exit(s, "closing the window with no console edit quits at once")
assert(asks(s) == 0, "nothing was asked")
s.pipe:close()
s = H.start { dir = dir .. "/s5", script = script, size = "240x180" }
s:wait_frame(1)
s:send("net.layers[1].weight[1][2] = -0.4")
s:wait_frame(2)
x11:close_window()
s:wait_log("close the window again %(or press Q%) to quit")
H.sleep(0.3)
assert(alive(s), "the first close after an edit does not quit")
x11:close_window()
wait_exit(s, "a second close within 3 s quits")
s.pipe:close()

-- 5. Esc just after a training ended asks first; Esc again quits.
local train_script = dir .. "/train.lua"
H.write(train_script, ([[
local sn = require "shadenet"
local net = sn.keep("net", function()
  local data = sn.dataset.sample { target = sn.lighting.phong {}, n = 400000, seed = 1 }
  local n = sn.mlp { inputs = 6, hidden = { 32, 32 }, outputs = 3, seed = 1 }
  sn.train { nets = n, data = data, epochs = 1, batch = 8, backend = "cpu" }
  io.stderr:write("TRAINED\n")
  return n
end)
sn.live.show { network = function(view)
  local t = sn.target { width = view.width, height = view.height }
  t:clear { 0.5 + 0.1 * net.layers[1].weight[1][1], 0.5, 0.5, 1 }
  return t
end }
]]))
s = H.start { dir = dir .. "/s6", script = train_script, size = "240x180", limit = 60 }
s:wait_log("TRAINED", 50)
x11:move(120, 90)
x11:key("Escape")
local LATE = "The work had ended before the key was read %(nothing was cancelled%): press Esc %(or Q%) again to quit"
for _ = 1, 50 do
  if s:log():find(LATE) or not alive(s) then break end
  H.sleep(0.02)
end
if alive(s) and not s:log():find(LATE) then x11:key("Escape") end  -- a key XTest lost
s:wait_log(LATE)
assert(alive(s), "an Esc just after the training does not quit")
x11:key("Escape")
wait_exit(s, "Esc again quits")
s.pipe:close()
x11:close()
print("quit: at once without edits, asked (window + terminal) after a console edit, asked again after 3 s, at once after a reload; "
      .. "the close button alike; an Esc just after a training asks")

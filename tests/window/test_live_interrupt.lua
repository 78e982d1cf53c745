-- An endless loop never hangs a live session: Esc in the window stops Lua that runs without end
-- (a console line, a loop whose pcall would swallow the error, the script after a save), the
-- window says what runs meanwhile, and the session keeps its last good state (the network, the
-- picture) and goes on: later lines run, later saves reload. A console line that fails puts back
-- the networks it changed, so the picture is the one before it and Q has nothing to ask; a
-- console sn.train cancelled with Esc leaves the network as it was. (Ctrl-C at the terminal:
-- tests/lua/test_live_interrupt.lua.)
local sn = require "shadenet"
package.path = "tests/live/?.lua;" .. package.path
local H = require "harness"

local dir = "out/live_tests/interrupt"
local script, template = H.scenario(dir)

local s = H.start { dir = dir .. "/session", script = script, size = "160x120", shown = true, limit = 90 }
s:wait_frame(1)
local first = s:image(1)
local x11 = H.x11()
x11:move(80, 60)
local function count(pattern) return select(2, s:log():gsub(pattern, "")) end
-- Light pixels in the top left corner of a shown picture: the text of a bar across the top (the
-- picture there is background).
local function bar_text(pic)
  local n = 0
  for y = 1, 16 do
    for x = 1, 60 do
      local p = pic:get(x, y)
      if p[1] + p[2] + p[3] > 1.5 then n = n + 1 end
    end
  end
  return n
end
-- Presses Esc once what runs shows its bar (after half a second), then waits for the log to say
-- it stopped; returns the picture with the bar. (XTest keys have been seen to go missing under
-- Xvfb: one more press if nothing happened within 3 s; none more, a spare Esc would be a quit.)
local function esc_stops(pattern, what)
  local n, shown = count(pattern), nil
  for _ = 1, 400 do
    local _, pic = s:shown()
    if pic and bar_text(pic) > 20 then
      shown = pic
      break
    end
    H.sleep(0.05)
  end
  if not shown then s:fail("no bar was shown while " .. what .. " ran") end
  for _ = 1, 2 do
    x11:key("Escape")
    for _ = 1, 150 do
      if count(pattern) > n then return shown end
      H.sleep(0.02)
    end
  end
  s:fail("Esc did not stop " .. what)
end
local function alive(tag)
  s:send(("print('%s ' .. net.layers[1].weight[1][2])"):format(tag))
  return tonumber(s:wait_log(tag .. " (%S+)\n"))
end
local w12 = alive("W0")

-- 1. A console line that never ends, after an edit: Esc stops it, the edit is undone (the line
-- failed), the session goes on.
s:send("net.layers[1].weight[1][2] = -0.4; while true do end")
local running = esc_stops("stdin:1: interrupted by the user %(Esc%)", "a console loop")
assert(alive("W1") == w12, "the failed line's edit was put back")
-- While it ran, the window showed the last good picture under the bar: the middle as it was.
local middle = 0
for x = 1, 160, 2 do
  local p, q = running:get(x, 60), first:get(x, 60)
  if math.abs(p[1] - q[1]) + math.abs(p[2] - q[2]) + math.abs(p[3] - q[3]) > 0.05 then middle = middle + 1 end
end
assert(middle == 0, ("the last good picture under the bar: %d of 80 changed in the middle"):format(middle))

-- 2. A loop that catches every error in a pcall: the interruption still ends the line.
s:send("while true do pcall(function() while true do end end) end")
esc_stops("stdin:1: interrupted by the user %(Esc%).*stdin:1: interrupted by the user %(Esc%)", "a pcall loop")
alive("W2")
-- The picture after the failed lines is the first one: nothing they did stayed.
local n = s:settle()
assert(H.same(s:image(n), first), "the picture after the interrupted lines is the last good one")

-- 3. A save that loops for ever: Esc stops the run, the error names the script's line, and the
-- kept network and the picture stay; the next good save runs.
H.write(script, template .. "\nlocal spin = 0\nwhile true do spin = spin + 1 end\n")
esc_stops("error: [^\n]*scenario%.lua:%d+: interrupted by the user %(Esc%)", "the script's loop")
assert(alive("W3") == w12, "the kept network is the last good run's")
local runs = count("%[live%] ran ")
H.write(script, template .. "\n-- fixed\n")
for _ = 1, 400 do
  if count("%[live%] ran ") > runs then break end
  H.sleep(0.05)
end
assert(count("%[live%] ran ") > runs, "the next save ran")
print("1-3. Esc stopped a console loop, a pcall loop and a looping script; the session went on with its last good state")

-- 4. A console sn.train cancelled with Esc: the network keeps the weights it had before.
local before = alive("W4")
s:send("rows = sn.dataset.sample { target = sn.lighting.phong {}, n = 200000, seed = 5 }")
s:send("io.stderr:write('TRAIN GO\\n'); sn.train { nets = net, data = rows, epochs = 100000, batch = 8, backend = 'cpu' }")
s:wait_log("TRAIN GO", 60)
esc_stops("stdin:1: sn.train: cancelled by the user %(Esc%) in epoch %d+ of 100000", "the console's training")
assert(alive("W5") == before, "the cancelled training left the network as it was")

-- 5. A failed console line counts as no edit: after a reload (the edits above are gone with it),
-- a line that edits and then fails redraws the same picture, and Q quits at once.
local f0 = s:frames()
H.write(script, template .. "\n-- saved again\n")
s:wait_frame(f0 + 1)
s:send("net.layers[1].weight[1][2] = 3; error('oops')")
s:wait_log("stdin:1: oops")
s:wait_frame(f0 + 2)
assert(H.same(s:image(f0 + 2), s:image(f0 + 1)), "the picture after the failed line is the one before it")
x11:key("q")
for _ = 1, 200 do
  if not H.exists(("/proc/%d/stat"):format(s.pid)) or (H.read(("/proc/%d/stat"):format(s.pid)):match("%) (%a)")) == "Z" then
    break
  end
  H.sleep(0.05)
end
assert(not s:log():find("again to quit", 1, true), "Q asked before quitting after a failed line:\n" .. s:log())
assert(not H.exists(("/proc/%d/stat"):format(s.pid)) or H.read(("/proc/%d/stat"):format(s.pid)):match("%) (%a)") == "Z",
       "Q quit")
s.pipe:close()
x11:close()
print("4-5. a cancelled console training and a failed line left the network as it was; Q had nothing to ask")

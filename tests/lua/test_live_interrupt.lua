-- Ctrl-C at the terminal stops Lua that runs without end in a live session (headless here; Esc
-- in a window: tests/window/test_live_interrupt.lua): a console line, a console training, the
-- script after a save. Each stops with "interrupted by the user (Ctrl-C)" at its line, the kept
-- network stays as it was, and the session goes on.
local sn = require "shadenet"
package.path = "tests/live/?.lua;" .. package.path
local H = require "harness"

local dir = "out/live_tests/interrupt_headless"
local script, template = H.scenario(dir)

local s = H.start { dir = dir .. "/session", script = script, window = false, sigint = true, limit = 90 }
s:wait_log("%[live%] ran ")
local function count(pattern) return select(2, s:log():gsub(pattern, "")) end
local function ctrl_c(pattern, what)
  local n = count(pattern)
  H.sleep(0.5)
  os.execute("kill -INT " .. s.pid)
  for _ = 1, 250 do
    if count(pattern) > n then return end
    H.sleep(0.02)
  end
  s:fail("Ctrl-C did not stop " .. what)
end
local marks = 0
local function weight()
  marks = marks + 1
  s:send(("print('W%d ' .. net.layers[1].weight[1][2])"):format(marks))
  return tonumber(s:wait_log(("W%d (%%S+)\n"):format(marks)))
end
local w = weight()

-- 1. A console line that edits, then never ends.
s:send("net.layers[1].weight[1][2] = -0.4; while true do end")
ctrl_c("stdin:1: interrupted by the user %(Ctrl%-C%)", "a console loop")
assert(s:log():find("[live] interrupt: stopping the script (Ctrl-C again to end shadenet at once)", 1, true),
       "the terminal says what Ctrl-C does and what a second one would")
assert(weight() == w, "the edit of the interrupted line was put back")

-- 2. A training typed at the console stops at its next tick, and the network is as it was.
s:send("rows = sn.dataset.sample { target = sn.lighting.phong {}, n = 200000, seed = 5 }")
s:send("io.stderr:write('TRAIN GO\\n'); sn.train { nets = net, data = rows, epochs = 100000, batch = 8, backend = 'cpu' }")
s:wait_log("TRAIN GO", 60)
ctrl_c("stdin:1: sn.train: interrupted by the user %(Ctrl%-C%) in epoch %d+ of 100000", "the console's training")
assert(weight() == w, "the interrupted training left the network as it was")

-- 3. A save that loops for ever: the error names the script's line; the next save runs.
H.write(script, template .. "\nlocal spin = 0\nwhile true do spin = spin + 1 end\n")
ctrl_c("error: [^\n]*scenario%.lua:%d+: interrupted by the user %(Ctrl%-C%)", "the script's loop")
assert(weight() == w, "the kept network is the last good run's")
local runs = count("%[live%] ran ")
H.write(script, template .. "\n-- fixed\n")
for _ = 1, 400 do
  if count("%[live%] ran ") > runs then break end
  H.sleep(0.05)
end
assert(count("%[live%] ran ") > runs, "the next save ran")
assert(s:stop(), "the session ended when asked")
print("Ctrl-C stopped a console loop, a console training and a looping script; the session went on")

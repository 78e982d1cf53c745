-- Redraw only when something changed: an idle window neither redraws nor burns CPU. The bound:
-- less than 5% of one core over 3 seconds (measured: ~0.2%, see docs/live-mode.md).
local sn = require "shadenet"
package.path = "tests/live/?.lua;" .. package.path
local H = require "harness"

local dir = "out/live_tests/idle"
local script = H.scenario(dir)

local s = H.start { dir = dir, script = script, size = "320x240" }
s:wait_frame(1)
local n = s:settle()
H.sleep(0.5)
local cpu0, t0 = s:cpu_seconds(), sn.clock()
H.sleep(3)
local cpu, wall = s:cpu_seconds() - cpu0, sn.clock() - t0
assert(s:frames() == n, ("the idle window redrew %d times"):format(s:frames() - n))
local share = cpu / wall
print(("idle window: %.3f s CPU over %.2f s = %.2f%% of one core, no redraw"):format(cpu, wall, share * 100))
assert(share < 0.05, "an idle window should use almost no CPU")

-- Not asleep for good: a console line still wakes it at once.
local t1 = sn.clock()
s:send("sn.live.redraw()")
s:wait_frame(n + 1, 5)
print(("woken by the console in %.0f ms"):format((sn.clock() - t1) * 1e3))
s:stop()

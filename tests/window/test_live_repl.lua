-- The console: lines piped to stdin run in the script's state (its top-level locals included),
-- print their values as the lua interpreter does, and the window redraws after each. A weight
-- edit, a multi-line function and a view switch all change what is shown.
local sn = require "shadenet"
package.path = "tests/live/?.lua;" .. package.path
local H = require "harness"

local dir = "out/live_tests/repl"
local script = H.scenario(dir)

local s = H.start { dir = dir, script = script }
s:wait_frame(1)
local trained = s:image(1)

-- An expression prints its values; `net` is the script's local.
s:send("net:trained_steps(), #net.layers")
assert(s:wait_log("\n(%d+\t3)\n"), "the expression's values were printed")

-- A weight edit from the console shows in the next frame.
s:send("net.layers[1].weight[1][2] = -0.4")
local n = s:settle()
local edited = s:image(n)
assert(not H.same(edited, trained), "the console's weight edit changed the picture")
local x, y = 80, 60
local before, after = trained:get(x, y), edited:get(x, y)
assert(after[2] < before[2] and math.abs(after[1] - before[1]) < 1e-6,
       ("green fell, red stayed: %g -> %g, %g -> %g"):format(before[2], after[2], before[1], after[1]))

-- A function over several lines, then a call: the chunk waits for its `end`.
s:send("function dim(k)")
s:send("  for c = 1, 3 do net.layers[1].weight[1][c] = net.layers[1].weight[1][c] - k end")
s:send("end")
s:send("dim(0.25)")
local n2 = s:settle()
assert(not H.same(s:image(n2), edited), "the multi-line edit changed the picture")

-- Errors are reported with stdin:LINE and change nothing.
s:send("net.layers[9].weight[1][1] = 0")
local err = s:wait_log("(stdin:1: [^\n]*)")
assert(err:find("layer", 1, true), "the error names the layer: " .. err)

-- The view follows the console too: the truth is the fixed-colour sphere.
s:send("sn.live.set_view{ mode = 'truth' }")
local truth = s:image(s:settle())
local t = truth:get(x, y)
assert(math.abs(t[1] / t[3] - 0.8 / 0.3) < 1e-4, "the truth view shows the truth colour")
s:stop()
print("console: values printed, weight edits and view switches redrawn, errors at stdin:1")

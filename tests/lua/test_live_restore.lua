-- What live mode puts back, driven through the loop's own Lua functions (the C++ loop calls them
-- around each run and console line; tests/window/test_live_interrupt.lua drives a real session):
-- 1. a reload puts a kept network's condition inputs (net:set_input) back with its weights, so
--    deleting a set_input edit undoes it and a console set_input lasts until the next reload;
-- 2. a console line that fails puts back every network it changed (kept ones, the show's, the
--    script's top-level locals) and drops the view it asked for; a line that succeeds keeps its edits.
local sn = require "shadenet"
local live = sn.live

local scene = sn.scene { mesh = sn.mesh.sphere { segments = 16, rings = 8 }, size = { 24, 24 }, views = { count = 2 } }
local data = scene:dataset { target = sn.lighting.ggx {}, vary = { roughness = { 0.1, 0.8 } },
                             inputs = { "normal", "view", "roughness" }, samples = 300 }
local net = sn.keep("conditioned", function()
  local n = sn.mlp { inputs = 7, hidden = { 4 }, seed = 1 }
  sn.train { nets = { n }, data = data, epochs = 1, batch = 8, backend = "cpu" }
  return n
end)
local function input() return net:conditions()[1].value end
local function near(a, b, what) assert(math.abs(a - b) < 1e-6, ("%s: %.9g, expected %.9g"):format(what, a, b)) end
local v0, w0 = input(), net.layers[1].weight[1][1]

-- 1. Condition inputs across reloads.
live._begin_run(); live._end_run(true)        -- a run of the script as it is
net:set_input("roughness", 0.2)               -- a console edit
live._begin_run()                             -- the next reload: the script is the truth again
near(input(), v0, "a reload puts a console set_input back")
net:set_input("roughness", 0.7)               -- the script's edit
live._end_run(true)
near(input(), 0.7, "a good run's set_input is the good state")
live._begin_run()                             -- the edit deleted from the script
near(input(), v0, "deleting a set_input edit undoes it")
live._end_run(true)
live._begin_run()
net:set_input("roughness", 0.3)
net.layers[1].weight[1][1] = 2
live._end_run(false)                          -- a run that edits, then fails
near(input(), v0, "a failed run puts the input back as the last good run left it")
near(net.layers[1].weight[1][1], w0, "and the weights")

-- 2. Console lines. The show's network and a top-level local network are not kept; they are put
-- back too.
local shown = sn.mlp { inputs = 6, hidden = { 3 }, outputs = 3, seed = 2 }
local script_local = sn.mlp { inputs = 6, hidden = { 3 }, outputs = 3, seed = 3 }
live.show { scene = scene, network = shown }
live._set_locals { script_local = script_local, net = net }
local s0, l0 = shown.layers[1].bias[1], script_local.layers[2].weight[1][1]
live._line_begin()
net.layers[1].weight[1][1] = 3
net:set_input("roughness", 0.5)
shown.layers[1].bias[1] = 7
script_local.layers[2].weight[1][1] = -7
live.set_view { mode = "truth" }
live._line_end(false)                         -- the line raised an error after all that
near(net.layers[1].weight[1][1], w0, "a failed line puts the kept network's weight back")
near(input(), v0, "and its input")
near(shown.layers[1].bias[1], s0, "and the show's network")
near(script_local.layers[2].weight[1][1], l0, "and a network among the script's locals")
local _, _, view = live._take_requests()
assert(view == nil, "the view the failed line asked for is dropped")

live._line_begin()
net.layers[1].weight[1][1] = 3
live.set_view { mode = "truth" }
live._line_end(true)
near(net.layers[1].weight[1][1], 3, "a line that ran keeps its edit")
_, _, view = live._take_requests()
assert(view and view.mode == "truth", "and its view")
print("reloads put condition inputs back; a failed console line puts back every network it changed")

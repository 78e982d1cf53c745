-- sn.live.bind: a key steps a weight (a Lua expression), a parameter of the show's lighting model
-- or a conditioning input of its network, up (the key) and down (Shift), within min/max; the
-- rendered view follows; bad bindings are errors naming the valid choices. (Real keys in a
-- window: tests/window/test_live_bind.lua.)
local sn = require "shadenet"
local live = sn.live

local fails = require("expect").fails
local function near(a, b, what) assert(math.abs(a - b) < 1e-6, ("%s: %.9g, expected %.9g"):format(what, a, b)) end

local scene = sn.scene { mesh = sn.mesh.sphere { segments = 24, rings = 12 }, size = { 48, 48 }, views = { count = 4 },
                         light = { dir = { 0.3, 0.6, 0.8 } } }
local data = scene:dataset { target = sn.lighting.ggx {}, vary = { roughness = { 0.1, 0.8 } },
                             inputs = { "normal", "view", "roughness" }, samples = 600 }
net = sn.mlp { inputs = 7, hidden = { 6 }, seed = 1 }  -- a global: bound expressions see globals
sn.train { nets = { net }, data = data, epochs = 1, batch = 8, backend = "cpu" }
local ggx = sn.lighting.ggx { roughness = 0.3 }
live.show { scene = scene, network = net, truth = ggx }

-- 1. A weight, by expression: k steps up, K (Shift) down, clamped to max.
local w0 = net.layers[1].weight[2][3]
live.bind { key = "k", param = "net.layers[1].weight[2][3]", step = 0.25, max = w0 + 0.3 }
local line = live._key("k", false)
near(net.layers[1].weight[2][3], w0 + 0.25, "k steps the weight up")
assert(line:find("^net%.layers%[1%]%.weight%[2%]%[3%] = "), "the terminal's line names the weight: " .. line)
live._key("k", false)
near(net.layers[1].weight[2][3], w0 + 0.3, "clamped to max")
live._key("k", true)
near(net.layers[1].weight[2][3], w0 + 0.05, "Shift+k steps down")
assert(live._key("z", false) == nil, "an unbound key does nothing")
-- Binding a bound key again (its capital too: Shift steps down) replaces it, and says so.
local said = {}
local print0 = print
print = function(...) said[#said + 1] = table.concat({ ... }, " ") end
live.bind { key = "K", param = "net.layers[1].weight[2][4]" }
live.bind { key = "k", param = "net.layers[1].weight[2][3]", step = 0.25, max = w0 + 0.3 }
print = print0
assert(said[1] == "[live] key k was bound to net.layers[1].weight[2][3]; now to net.layers[1].weight[2][4]", said[1])
assert(#said == 2, "and back: " .. #said)

-- 2. The show's lighting model: a changed copy replaces it; the truth view shows it.
local before = live.render { mode = "truth" }:read()
live.bind { key = "g", param = "truth.roughness", step = 0.1, min = 0.05, max = 1 }
live._key("g", false)
near(ggx:params().roughness, 0.3, "the model given is not changed (models are values)")
local after = live.render { mode = "truth" }:read()
assert(sn.image.mse(before, after) > 1e-6, "the truth view follows the roughness")
local want = scene:render(sn.lighting.ggx { roughness = 0.4 })
assert(sn.image.mse(after, want) < 1e-10, "it is GGX at roughness 0.4")
for _ = 1, 12 do live._key("g", false) end
near(live.binds()[1].value, 1, "clamped to max = 1 (g is the first binding by key)")

-- 3. A conditioning input: its trained range is the default min/max.
live.bind { key = "u", param = "input.roughness", step = 0.2 }
local v0 = net:conditions()[1].value
live._key("u", true)
near(net:conditions()[1].value, v0 - 0.2, "Shift+u lowers the input")
for _ = 1, 5 do live._key("u", true) end
near(net:conditions()[1].value, 0.1, "clamped to the trained range's min")

-- 4. get/set functions, and the HUD's lines.
local x = 1
live.bind { key = "9", name = "x", get = function() return x end, set = function(v) x = v end }
live._key("9", false)
near(x, 1.1, "get/set with the default step 0.1")
local lines = live._bind_lines()
assert(#lines == 4 and lines[1]:find("^9/9  x = 1%.1$") and lines[2]:find("^g/G  truth%.roughness = 1$"),
       "the HUD lists the keys, names and values: " .. table.concat(lines, " | "))

-- 5. Errors name the valid choices.
fails(function() live.bind { key = "s", param = "x" } end, "key 's' cannot be bound (free keys: a b d e f g j k")
fails(function() live.bind { key = "k", param = "truth.colour" } end, "not a number parameter of ggx (valid: roughness")
fails(function() live.bind { key = "k", param = "input.metal" } end, "has no input 'metal' (conditions: roughness)")
fails(function() live.bind { key = "k", param = "net.layers[1] +" } end, "is not an assignable Lua expression")
fails(function() live.bind { key = "k", param = "x", stepp = 1 } end, "unknown option 'stepp' (valid: key, param, step")
fails(function() live.bind { key = "k", param = "x", min = 2, max = 1 } end, "'min' must be below 'max'")
live.bind { key = "b", param = "nothing_here" }
local none, err = live._key("b", false)
assert(none == nil and err:find("nothing_here is nil, not a number", 1, true), "a bad expression at the key: " .. tostring(err))

-- 6. In a plain run (no console collects the script's locals) an expression may name the
-- script's locals, as under --watch: binds() shows their values and the key steps them.
local local_net = sn.mlp { inputs = 6, hidden = { 3 }, outputs = 3, seed = 4 }
local lw = local_net.layers[2].weight
live.bind { key = "l", param = "local_net.layers[2].weight[1][2]", step = 0.5 }
live.bind { key = "m", param = "lw[3][1]" }
local seen = {}
for _, b in ipairs(live.binds()) do seen[b.key] = b.value end
assert(seen.l and math.abs(seen.l - local_net.layers[2].weight[1][2]) < 1e-7,
       "binds() reads an expression over a local network: " .. tostring(seen.l))
assert(seen.m and math.abs(seen.m - lw[3][1]) < 1e-7, "and over a local table: " .. tostring(seen.m))
local l0 = local_net.layers[2].weight[1][2]
live._key("l", false)
near(local_net.layers[2].weight[1][2], l0 + 0.5, "the key steps the local network's weight")
print("bind: a weight, truth.roughness, input.roughness and get/set step up and down within their ranges; errors name the choices; locals are seen in a plain run")

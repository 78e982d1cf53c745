-- Networks from Lua: construction, tostring, weight and bias views, whole-layer tables, the
-- version counter, the flat parameter layout, clone, save/load.
local sn = require "shadenet"

local function near(a, b, tol, what)
  assert(math.abs(a - b) <= (tol or 1e-6), string.format("%s: %.9g vs %.9g", what or "value", a, b))
end

local net = sn.mlp { inputs = 6, hidden = {13, 13, 13, 13, 6, 6, 6, 6}, outputs = 3, activation = "tanh", seed = 1 }
assert(tostring(net) == "mlp(6 -> 13x4 -> 6x4 -> 3, tanh)", tostring(net))
assert(#net.layers == 9, "layers: " .. #net.layers)
assert(net.layers[1].inputs == 6 and net.layers[1].outputs == 13, "layer 1 widths")
assert(net.layers[9].inputs == 6 and net.layers[9].outputs == 3, "layer 9 widths")
assert(net.layers[1].activation == "tanh" and net.layers[9].activation == "linear", "activations")
assert(#net.layers[5].weight == 6 and #net.layers[5].weight[1] == 13 and #net.layers[5].bias == 6, "view lengths")
assert(tostring(sn.mlp { inputs = 6, hidden = {8}, outputs = 3, activation = "leaky_relu", slope = 0.2,
                          color = "hsv", output_activation = "sigmoid" })
       == "mlp(6 -> 8 -> 3, leaky_relu 0.2, out sigmoid, hsv)")

-- Xavier: layer 1 weights within sqrt(6 / (6 + 13)), biases 0; the seed decides the values.
local limit = math.sqrt(6 / 19)
local W = net.layers[1].weight:table()
assert(#W == 13 and #W[1] == 6, "weight table shape")
for r = 1, 13 do for c = 1, 6 do assert(math.abs(W[r][c]) <= limit, "xavier limit") end end
for r = 1, 13 do assert(net.layers[1].bias[r] == 0, "bias starts at 0") end
local same = sn.mlp { inputs = 6, hidden = {13, 13, 13, 13, 6, 6, 6, 6}, outputs = 3, seed = 1 }
local other = sn.mlp { inputs = 6, hidden = {13, 13, 13, 13, 6, 6, 6, 6}, outputs = 3, seed = 2 }
assert(same.layers[2].weight[3][4] == net.layers[2].weight[3][4], "same seed, same weights")
assert(other.layers[2].weight[3][4] ~= net.layers[2].weight[3][4], "other seed, other weights")

-- Element edits bump the version; values are stored as float.
local v0 = net:version()
net.layers[1].weight[2][3] = 0.7
near(net.layers[1].weight[2][3], 0.7, 1e-7, "weight[2][3]")
net.layers[3].bias[5] = -0.25
assert(net.layers[3].bias[5] == -0.25, "bias[5]")
assert(net:version() == v0 + 2, "version after two edits: " .. net:version())

-- Whole layers as tables, and single rows.
local rows = {}
for r = 1, 13 do rows[r] = {} for c = 1, 6 do rows[r][c] = r + c / 10 end end
net.layers[1].weight = rows
near(net.layers[1].weight[13][6], 13.6, 1e-6, "whole-layer set")
net.layers[9].bias = {1, 2, 3}
assert(net.layers[9].bias[3] == 3, "whole bias set")
net.layers[9].weight[2] = {6, 5, 4, 3, 2, 1}
assert(net.layers[9].weight[2][1] == 6 and net.layers[9].weight[2][6] == 1, "row set")
local b = net.layers[9].bias:table()
assert(#b == 3 and b[2] == 2, "bias table")

-- The flat layout: layer 1 weights row-major [out][in], then its biases, then layer 2 ...
local p = net:params()
assert(#p == (6 * 13 + 13) + 3 * (13 * 13 + 13) + (13 * 6 + 6) + 3 * (6 * 6 + 6) + (6 * 3 + 3), "param count " .. #p)
near(p[(2 - 1) * 6 + 3], 2.3, 1e-6, "flat weight [2][3]")
near(p[6 * 13 + 1], net.layers[1].bias[1], 0, "flat bias 1")
near(p[6 * 13 + 13 + 1], net.layers[2].weight[1][1], 0, "layer 2 starts after layer 1's biases")
p[1] = 0.5
net:set_params(p)
assert(net.layers[1].weight[1][1] == 0.5, "set_params")

-- clone is independent.
local copy = net:clone()
copy.layers[1].weight[1][1] = -3
assert(net.layers[1].weight[1][1] == 0.5 and copy.layers[1].weight[1][1] == -3, "clone independent")
assert(net ~= copy and net == net, "identity")

-- Spec as a table.
local s = net:spec()
assert(s.inputs == 6 and s.outputs == 3 and #s.hidden == 8 and s.hidden[5] == 6 and s.color == "rgb", "spec")

-- Save and load keep every weight and the input names.
local named = sn.mlp { inputs = 6, hidden = {4}, outputs = 3, input_names = {"normal", "view"}, seed = 9 }
named.layers[2].weight[3][4] = 0.123
local path = sn.fs.tempdir("test_mlp") .. "/net.snmlp"
named:save(path)
local back = sn.load(path)
assert(tostring(back) == tostring(named), "loaded spec")
assert(back.layers[2].weight[3][4] == named.layers[2].weight[3][4], "loaded weight")
local bp, np = back:params(), named:params()
for i = 1, #np do assert(bp[i] == np[i], "param " .. i) end
assert(table.concat(back:inputs(), ",") == "normal,view", "input names")
assert(back:best() == nil and back:restore_best() == false, "no best snapshot before training")

-- Views outlive nothing: after release they say so.
local layer = named.layers[1]
named:release()
local ok, err = pcall(function() return layer.weight[1][1] end)
assert(not ok and err:find("this Mlp was released"), tostring(err))
-- A view keeps its network from the collector (a net held by nothing else than its views).
local held = sn.mlp { inputs = 2, hidden = { 3 }, outputs = 1, seed = 1 }
local w, row = held.layers[1].weight, held.layers[2].weight[1]
local w11, r1 = w[1][1], row[1]
held = nil
collectgarbage()
collectgarbage()
assert(w[1][1] == w11 and row[1] == r1 and #w == 3, "views of a collected-looking net still read it")
-- Input names that cannot describe the inputs are refused by sn.mlp itself, not at the first
-- render or training; a dataset of 2 rows split 0.8 (no validation row) by sn.dataset.
local expect = require "expect"
expect.fails(function() sn.mlp { inputs = 6, hidden = { 4 }, input_names = { "normal", "view", "uv" } } end,
             "sn.mlp: input_names {normal, view, uv} describe 8 input columns (normal 3, view 3, uv 2;")
expect.fails(function() sn.mlp { inputs = 6, hidden = { 4 }, input_names = { "foo", "bar" } } end, "describe 2 input columns")
assert(sn.mlp { inputs = 7, hidden = { 4 }, input_names = { "normal", "view", "roughness" } }, "a condition is 1 column")
local two = sn.dataset { x = { { 1 }, { 2 } }, y = { { 1 }, { 2 } } }
assert(select(1, two:counts()) == 1 and select(2, two:counts()) == 1, "2 rows at 0.8: one of each")
local tiny = sn.dataset { x = { { 1 }, { 2 }, { 3 } }, y = { { 1 }, { 2 }, { 3 } }, split = 0.1 }
assert(select(1, tiny:counts()) == 1 and select(2, tiny:counts()) == 2, "3 rows at 0.1: one to train on")
expect.fails(function() sn.dataset { x = { { 1 }, { 2 } }, y = { { 1 }, { 2 } }, split = 0 } end, "must be in (0, 1], got 0")
local all = sn.dataset { x = { { 1 }, { 2 } }, y = { { 1 }, { 2 } }, split = 1 }
expect.fails(function() sn.train { nets = { sn.mlp { inputs = 1, hidden = { 2 }, outputs = 1 } }, data = all, epochs = 1, batch = 1 } end,
             "the dataset has no validation rows (all 2 train): make it with a split below 1")
print("test_mlp ok")

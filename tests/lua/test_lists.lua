-- Lists given to the API are strict (lua/binding.h, check_list): a named key among the elements,
-- or an element after a nil, is an error naming the key. Reading only 1..#t would drop it
-- unseen: a sweep's misspelt option, a net:forward sample past a hole, a light given bare.
local sn = require "shadenet"
local expect = require "expect"

local net = sn.mlp { inputs = 6, hidden = { 4 }, outputs = 3 }
local x = { 0.1, 0.2, 0.3, 0.4, 0.5, 0.6 }

-- The well-formed lists work, and their values arrive (not a test that passes on an error).
local y = net:forward { x, x }
assert(#y == 2 and y[1][3] == y[2][3], "two samples, the same outputs")
assert(sn.buffer { type = "float32", data = { 1, 2, 3 } }:download()[3] == 3, "a buffer's data list")

expect.fails(function() return net:forward { x, x, n = 2 } end, "net:forward: a list expected, got a table with the key 'n'")
expect.fails(function() return net:forward { x, nil, x } end, "net:forward: a list expected, got a")
expect.fails(function() return net:forward { x, nil, x } end, "nil at [2]")
expect.fails(function() return sn.buffer { type = "float32", data = { 1, 2, scale = 4 } } end,
             "sn.buffer option 'data': a list expected, got a table with the key 'scale'")
expect.fails(function() return sn.buffer { type = "float32", data = { 1, 2, [4] = 4 } } end,
             "sn.buffer option 'data': a list expected, got a nil at [3] before [4]")
expect.fails(function() return sn.buffer { type = "float32", data = { 1, 2, [9] = 4 } } end, "the key [9] after a nil at [3]")
expect.fails(function() return sn.buffer { type = "float32", data = { 1, 2, [2.5] = 4 } } end, "the key [2.5]")
local b = sn.buffer { type = "float32", size = 4 }
expect.fails(function() b:upload { 1, 2, first = 3 } end, "buffer:upload: a list expected, got a table with the key 'first'")

-- A network's weights: a row with an extra named value is refused, not cut to its list.
local W = {}
for r = 1, 4 do W[r] = { 1, 2, 3, 4, 5, 6 } end
W[2].extra = 1
expect.fails(function() net.layers[1].weight = W end, "weight row 2: a list expected, got a table with the key 'extra'")
W[2].extra = nil
net.layers[1].weight = W
assert(net.layers[1].weight[2][6] == 6, "the rows, set")
expect.fails(function() net:set_params { 1, 2, extra = 3 } end, "net:set_params: a list expected, got a table with the key 'extra'")

-- Numbers lists (check_numbers): a transform or a direction with a stray key.
expect.fails(function() return sn.lighting.phong { light_dir = { 0, 1, 0, w = 1 } } end, "got a table with the key 'w'")
expect.fails(function() return sn.scene { mesh = { "meshes/test_blob.glb", transform = { scale = 2 } } } end,
             "sn.scene option 'mesh': a list expected, got a table with the key 'transform'")
expect.fails(function() return sn.scene { mesh = "meshes/test_blob.glb", poses = { {}, rotate = { 90, 0, 1, 0 } } } end,
             "sn.scene option 'poses': a list expected, got a table with the key 'rotate'")
expect.fails(function() return sn.scene { mesh = "meshes/test_blob.glb", views = { { count = 2 }, elevation = 30 } } end,
             "sn.scene option 'views': a list expected, got a table with the key 'elevation'")

-- A lighting model's attributes (sn.lighting.define) and a dataset's input names.
expect.fails(function()
  return sn.lighting.define { name = "lists_model", attributes = { "normal", "view", light = "light" },
                              glsl = "vec3 lists_model(Surface s) { return s.normal; }" }
end, "a list expected, got a table with the key 'light'")
expect.fails(function() return sn.dataset { x = { { 1 }, { 2 } }, y = { { 1 }, { 2 } }, input_names = { "a", b = "b" } } end,
             "sn.dataset option 'input_names': a list expected, got a table with the key 'b'")
-- Names must fit the rows (5 numbers named as 6 trained, then made a checkpoint sn.load refused).
local five = { { 0.5, 0, 1, 0, 0 }, { 0.25, 0, 1, 0, 0 } }
expect.fails(function() return sn.dataset { x = five, y = { { 1 }, { 2 } }, input_names = { "normal", "view" } } end,
             "sn.dataset option 'input_names': input names {normal, view} describe 6 columns, but the rows have 5 inputs")
expect.fails(function() return sn.dataset { x = five, y = { { 1 }, { 2 } }, input_names = { "uv", "uv", "x" } } end,
             "input name 'uv' is listed twice")
expect.fails(function() return sn.dataset { x = { { 1 }, { 2 }, extra = { 3 } }, y = { { 1 }, { 2 } } } end,
             "got a table with the key 'extra'")
print("lists: strict")

-- Seeds (lua/binding.h, check_seed): one rule everywhere, whole numbers in 0..2^53 (the
-- shuffles' in 0..2^32 - 1); a negative one was taken by sn.mlp as 2^64 - 1.
expect.fails(function() return sn.mlp { inputs = 2, hidden = { 2 }, outputs = 1, seed = -1 } end,
             "sn.mlp option 'seed' must be a whole number in 0..2^53, got -1")
expect.fails(function() return sn.mlp { inputs = 2, hidden = { 2 }, outputs = 1, seed = 1.5 } end, "got 1.5")
expect.fails(function() return sn.dataset { x = { { 1 }, { 2 } }, y = { { 1 }, { 2 } }, seed = 2 ^ 32 + 1 } end,
             "sn.dataset option 'seed' must be a whole number in 0..4294967295, got 4294967297")
local rows = {}
for i = 1, 40 do rows[i] = { i } end
local data = sn.dataset { x = rows, y = rows, seed = 4294967295 }
expect.fails(function() sn.train { nets = { net }, data = data, epochs = 1, seed = 2 ^ 32 } end,
             "sn.train option 'seed' must be a whole number in 0..4294967295, got 4294967296")
expect.fails(function() data:split { seed = -3 } end, "dataset:split option 'seed' must be a whole number in 0..")
local a, b = sn.mlp { inputs = 2, hidden = { 2 }, outputs = 1, seed = 2 ^ 53 }, sn.mlp { inputs = 2, hidden = { 2 }, outputs = 1, seed = 0 }
assert(not expect.same_params(a, b), "the largest seed and 0 draw different weights")
print("seeds: one rule")

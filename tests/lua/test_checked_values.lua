-- Values the API used to take silently and turn into something else: integers wrapped or
-- truncated by C casts, NaN and infinities passed on into pixels and colours, floats that
-- overflow where they are stored, a mask covering nothing scored as a perfect match. Each is an
-- error naming the script's line, the option and what is valid; the valid values still work.
local sn = require "shadenet"
local expect = require "expect"
local fails = expect.fails_here

-- ---- buf:fill takes what sn.buffer{fill = ...} takes (uint32 fill(-1) was 4294967295) ----
local u = sn.buffer { type = "uint32", size = 2 }
local i32 = sn.buffer { type = "int32", size = 2 }
fails(function() u:fill(-1) end, "buffer:fill value: -1 is not an integer in [0, 4294967295], the range of uint32")
fails(function() u:fill(1.7) end, "buffer:fill value: 1.7 is not an integer")
fails(function() u:fill(0 / 0) end, "buffer:fill value: nan is not an integer")
fails(function() i32:fill(3e9) end, "3e+09 is not an integer in [-2147483648, 2147483647], the range of int32")
u:fill(4294967295)
i32:fill(-2147483648)
assert(u:get(2) == 4294967295 and i32:get(2) == -2147483648, "the ends of the ranges fill")

-- ---- dispatch: workgroup counts and integer uniforms, checked before the casts ----
local square = sn.program { compute = "examples/square.comp", defines = { LOCAL_SIZE = 4 } }
local function run(groups, count, buffers)
  local b = sn.buffer { data = { 2, 2, 2, 2, 2, 2, 2, 2 } }
  square:dispatch { groups = groups, buffers = buffers or { b }, uniforms = { u_count = count } }
  return b:download()
end
fails(function() run(2 ^ 32 + 1, 8) end, "program:dispatch option 'groups': x must be a whole number in 1..")
fails(function() run(2 ^ 32 + 1, 8) end, "got 4294967297")  -- in full, not 4.29497e+09
fails(function() run(1.9, 8) end, "got 1.9")
fails(function() run(-1, 8) end, "got -1")  -- was "workgroup count 4294967295x1x1"
fails(function() run({ 1, 0 }, 8) end, "program:dispatch option 'groups': y must be a whole number in 1..")
fails(function() run(2, 2.7) end, "uniform 'u_count' (uint): 2.7 is not a whole number in 0..4294967295")
fails(function() run(2, -1) end, "uniform 'u_count' (uint): -1 is not a whole number in 0..4294967295")
fails(function() run(2, 0 / 0) end, "uniform 'u_count' (uint): nan is not")
-- A float uniform: NaN, an infinity or a double past float's range reached the shader as NaN or inf.
local poly = sn.program { compute = "tests/data/shaders/poly.comp", defines = { LOCAL_SIZE = 4 } }
local function scaled(scale)
  local ys = sn.buffer { size = 4 }
  poly:dispatch { groups = 1, buffers = { sn.buffer { data = { 1, 2, 3, 4 } }, ys }, uniforms = { u_count = 4, u_scale = scale } }
  return ys:download()
end
fails(function() scaled(0 / 0) end, "uniform 'u_scale' (float): nan is not a finite number in float's range")
fails(function() scaled(math.huge) end, "uniform 'u_scale' (float): inf is not a finite number")
fails(function() scaled(1e39) end, "uniform 'u_scale' (float): 1e+39 is not a finite number")
assert(math.abs(scaled(3e38)[1] - (3e38 * (1 - 2) + math.tanh(1))) <= 3e38 * 1e-6, "the largest floats still pass")
local b4 = sn.buffer { size = 4 }
fails(function() run(1, 4, { [true] = b4 }) end,
      "program:dispatch option 'buffers': the key boolean is neither a position (buffers[1] binds binding 0) nor a buffer block's name")
fails(function() run(1, 4, { [1.5] = b4 }) end, "program:dispatch option 'buffers': the key [1.5] is not a position 1, 2, ...")
fails(function() run(1, 4, { [0] = b4 }) end, "the key [0] is not a position")
local squared = run(2, 8)
assert(squared[1] == 4 and squared[8] == 4, "2 groups of 4 square all 8")

-- ---- mesh:transformed: positions finite as floats, an affine matrix only ----
local m = sn.mesh.sphere { segments = 8, rings = 4 }
fails(function() local r = m:transformed { scale = 1e39 }; return r end,
      "mesh:transformed: cannot transform mesh 'sphere': vertex 1 would land at")
fails(function() local r = m:transformed { scale = 1e39 }; return r end, "beyond a float's range (3.4e38)")
fails(function() local r = m:transformed { translate = { 1e39, 0, 0 } }; return r end, "would land at (1e+39, 1, 0)")
fails(function()
  local r = m:transformed { matrix = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 2 } }
  return r
end, "mesh:transformed option 'matrix': an affine transform expected, whose bottom row (elements 4, 8, 12, 16, column-major) is 0 0 0 1; got 0 0 0 2")
local moved = m:transformed { matrix = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 0, 0, 1 } }
assert(moved:bounds()[1] > 3, "an affine matrix moves the mesh")

-- ---- sn.image.mse: a mask covering no pixel is no score (it was 0, a perfect match) ----
local truth = sn.image.new { width = 16, height = 16, channels = 4, fill = 1 }
local render = sn.image.new { width = 16, height = 16, channels = 4, fill = 0 }
local nothing = sn.image.new { width = 16, height = 16, channels = 4, fill = 0 }
fails(function() local e = sn.image.mse(truth, render, { mask = nothing }); return e end,
      "the mask covers no pixel (its channel 4 is above 0.5 nowhere)")
assert(sn.image.mse(truth, render, { mask = truth }) == 1, "a covering mask scores")

-- ---- NaN and infinities in colours, directions and bounds ----
local img = sn.image.new { width = 64, height = 24, channels = 3, fill = 0 }
fails(function() img:text(2, 2, "Hi", { color = { 0 / 0, 1, 0 } }) end, "image:text option 'color': element 1 is nan; it must be finite")
fails(function() img:text(2, 2, "Hi", { color = { 0, 1 / 0, 0 } }) end, "element 2 is inf; it must be finite")
fails(function() img:text(2, 2, "Hi", { color = { 0, 0, 1e39 } }) end, "element 3 is 1e+39, beyond a float's range (3.4e38)")
fails(function() local g = sn.image.grid { panels = { img }, background = { 0 / 0, 0, 0 } }; return g end,
      "sn.image.grid option 'background': element 1 is nan")
local target = sn.target { width = 4, height = 4 }
fails(function() target:clear { 0 / 0, 0, 0, 1 } end, "target:clear colour: element 1 is nan; it must be finite")
local sphere = sn.mesh.sphere { segments = 8, rings = 4 }
local normals = sn.program { vertex = "mesh.vert", fragment = "normals.frag" }
fails(function() sn.draw { target = target, program = normals, mesh = sphere, camera = sn.camera {}, clear = { 0, 1 / 0, 0, 1 } } end,
      "sn.draw option 'clear': element 2 is inf; it must be finite")
local tp = sn.lighting.textured_phong {}
fails(function() local c = tp:shade { normal = { 0, 1, 0 }, view = { 0, 1, 0 }, base = { 0 / 0, 0.5, 0.5 } }; return c end,
      "model:shade option 'base': element 1 is nan; it must be finite")
local phong = sn.lighting.phong {}
fails(function() local c = phong:shade { normal = { 0 / 0, 1, 0 }, view = { 0, 1, 0 } }; return c end,
      "model:shade option 'normal': element 1 is nan")
fails(function() local c = phong:shade { normal = { 0, 1, 0 }, view = { 1 / 0, 1, 0 } }; return c end,
      "model:shade option 'view': element 1 is inf")
assert(phong:shade { normal = { 0, 1, 0 }, view = { 0, 1, 0 } }[1] > 0, "finite vectors shade")

local v3 = sn.vec3
local function lambert(name, bound)
  return sn.lighting.define {
    name = name, params = { k = { default = 0.9, range = { 0, 1 } } },
    glsl = "vec3 shade(Surface s, Params p) { return s.light_color * p.k * max(dot(s.n, s.l), 0.0); }",
    twin = function(s, p) return v3.scale(s.light_color, p.k * math.max(v3.dot(s.n, s.l), 0)) end,
    bound = bound }
end
local nan_bound = lambert("checked_nan_bound", function() return { 0 / 0, 0 / 0, 0 / 0 } end)
fails(function() local b = nan_bound:bound(); return b end,
      "lighting model 'checked_nan_bound': its bound returned {nan, nan, nan}; it must be finite")
-- sn.lighting.stress reported "failures 0" for it: now it fails, naming the bound.
fails(function() local r = sn.lighting.stress(nan_bound); return r end, "its bound returned {nan, nan, nan}")
local good = lambert("checked_good_bound", function(p, light) return v3.scale(light.color, 1) end)
assert(good:bound()[1] >= 0.9, "a finite bound is read")

-- ---- integers past 2^31 in figure calls (they wrapped through int casts) ----
local grid = sn.image.new { width = 8, height = 8, channels = 4 }
fails(function() local c = sn.image.crop(grid, 2 ^ 32 + 3, 1, 2, 2); return c end,
      "sn.image.crop x: integer within +-(2^31 - 1) expected, got 4294967299")
fails(function() local c = sn.image.crop(grid, 1, 1, 2 ^ 31 - 1, 2); return c end, "is not inside the 8x8 image")
fails(function() local c = sn.image.crop(grid, 2 ^ 31 - 1, 1, 2 ^ 31 - 1, 2); return c end, "is not inside the 8x8 image")
fails(function() local x = sn.image.covered_box(grid, 2 ^ 32 + 4); return x end,
      "sn.image.covered_box channel: integer within +-(2^31 - 1) expected, got 4294967300")
fails(function() img:text(2 ^ 32 + 2, 2, "wrapped") end, "image:text x: integer within +-(2^31 - 1) expected, got 4294967298")
img:text(2 ^ 31 - 1, -2 ^ 31 + 1, "far off")  -- in range, outside the image: draws nothing
assert(sn.image.crop(grid, 7, 7, 2, 2):size() == 2, "a crop inside the image")

-- ---- booleans, row widths, encoded values ----
fails(function() sn.catch_interrupt("no") end, "sn.catch_interrupt argument 1: boolean expected, got string")
fails(function() sn.catch_interrupt(0) end, "sn.catch_interrupt argument 1: boolean expected, got number")
sn.catch_interrupt(false)
local xs, ys = {}, {}
for k = 1, 8 do xs[k] = { k / 8, 0.25 } ys[k] = { 0.5, 0.5, 0.5 } end
fails(function() local d = sn.dataset { x = xs, y = ys, inputs = -3 }; return d end,
      "sn.dataset option 'inputs': a row width of at least 1 expected, got -3")
fails(function() local d = sn.dataset { x = xs, y = ys, outputs = 0 }; return d end, "sn.dataset option 'outputs': a row width")
assert(sn.dataset { x = xs, y = ys, inputs = 2 }:inputs() == 2, "a right width")

sn.encoding.define {
  name = "checked_logp", outputs = function(w) return w end,
  glsl = "return log(x[j] + 1.0);",
  lua = function(x) local o = {} for c = 1, #x do o[c] = math.log(x[c] + 1) end return o end,
}
local enc = sn.mlp { inputs = { "uv" }, hidden = { 4 }, encoding = { uv = "checked_logp" } }
fails(function() local e = enc:encode { -1, 0.25 }; return e end,
      "encoding 'checked_logp': lua returned -inf as output 1 for the input {-1, 0.25}; an encoding's outputs must be finite")
local ex = {}
for k = 1, 8 do ex[k] = { k % 2 == 0 and -1 or 0.5, 0.25 } end
local data = sn.dataset { x = ex, y = ys, input_names = { "uv" } }
fails(function() local r = sn.train { nets = enc, data = data, epochs = 1, batch = 2, backend = "cpu" }; return r end,
      "encoding 'checked_logp': lua returned -inf")
assert(math.abs(enc:encode { 0.5, 0.25 }[1] - math.log(1.5)) < 1e-9, "a finite input encodes")

-- ---- numbers checked before a cast or a computation that hid them ----
fails(function() local n = sn.mlp { inputs = 3, hidden = { 1e10 } }; return n end,
      "sn.mlp: hidden layer 1 width must be 1..64, got 1e+10")  -- was "got -2147483648"
fails(function() local n = sn.mlp { inputs = 3, hidden = { 4, -2 ^ 40 } }; return n end, "hidden layer 2 width must be 1..64")
fails(function() local o, d = sn.camera {}:ray(1, 1, 2 ^ 53, 2 ^ 53); return d end,
      "camera:ray width: integer within +-(2^31 - 1) expected, got 9007199254740992")
local scene_mesh = sn.mesh.sphere { segments = 8, rings = 4 }
local function scene(o)
  o.mesh, o.size = scene_mesh, { 8, 8 }
  local s = sn.scene(o)
  return s
end
fails(function() local s = scene { views = { count = 1 }, poses = { { translate = { 1e300, 0, 0 } } } }; return s end,
      "sn.scene option 'poses' element 1 option 'translate': element 1 is 1e+300, beyond a float's range (3.4e38)")
fails(function() local s = scene { poses = { { scale = 1e39 } } }; return s end, "option 'scale' is 1e+39, beyond a float's range")
fails(function() local s = scene { views = { count = 1, distance = 0 / 0 } }; return s end,
      "sn.scene option 'views' option 'distance' must be a number in (0, 1e38], got nan")
fails(function() local s = scene { views = { count = 1, distance = -2 } }; return s end, "got -2")
fails(function() local s = scene { views = { count = 1, elevation = 1 / 0 } }; return s end,
      "sn.scene option 'views' option 'elevation' is inf; it must be finite")
assert(scene { views = { count = 2, distance = 4 }, poses = { { translate = { 1, 0, 0 } } } }, "finite options make a scene")

print("checked values: ok")

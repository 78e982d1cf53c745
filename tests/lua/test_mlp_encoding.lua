-- Input encodings (sn.mlp{ encoding = {...} }), the built-ins and a user's (sn.encoding.define),
-- against the Lua reference of each one (tests/lua/encoding_reference.lua): what the first layer reads (net:encode, the double twins),
-- net:forward in a compute shader, the fragment shader of net:render, and two training steps on
-- the cpu and the gl backend against a Lua reference that takes its gradients by central
-- differences of the reference forward pass; checkpoints; net:spec() and tostring.
local sn = require "shadenet"
local encoding = require "encoding_reference"
local reference = require "reference_forward"
local forward = reference.forward

-- A user's encoding, defined in GLSL and Lua (sn.encoding.define), checked like the built-ins:
-- the powers x, x^2, .. x^n of each component. Its reference is written apart from its twin.
sn.encoding.define {
  name = "polynomial",
  count = { "degree", min = 1, max = 6, default = 3 },
  outputs = function(w, n) return w * n end,
  glsl = [[int c = j / n, k = j - c * n;
  float p = x[c];
  for (int i = 0; i < k; ++i) p *= x[c];
  return p;]],
  lua = function(x, n)
    local out = {}
    for _, v in ipairs(x) do
      local p = v
      for _ = 1, n do
        out[#out + 1] = p
        p = p * v
      end
    end
    return out
  end,
}
encoding.user.polynomial = function(e, x)
  local out = {}
  for c = 1, #x do
    for k = 1, e.degree do out[#out + 1] = x[c] ^ k end
  end
  return out
end

local cases = {
  { uv = { "frequency", bands = 4 } },
  { uv = { "frequency", bands = 9, include_input = false }, normal = "sh" },
  { uv = { "oneblob", bins = 8 } },
  { view = { "oneblob", bins = 6, range = { -1.2, 1.1 } } },
  { normal = { "sh", degree = 1 }, view = { "sh", degree = 3 } },
  { uv = "triangle_wave" },
  { uv = { "triangle_wave", bands = 5, include_input = true }, view = "identity" },
  { uv = { "polynomial", degree = 4 }, normal = "polynomial" },
}

-- Rows of (unit normal, unit view, uv) and a target with detail in uv. Inputs rounded to float,
-- as the network reads them (high frequency bands magnify a difference of 3e-8 in uv 800 times).
local f32 = require("ffi").new("float[1]")
local function float(v)
  f32[0] = v
  return f32[0]
end
local function unit(a, b, c)
  local l = math.sqrt(a * a + b * b + c * c)
  return float(a / l), float(b / l), float(c / l)
end
local x, y = {}, {}
for i = 1, 24 do
  local n1, n2, n3 = unit(math.sin(i * 1.3), math.cos(i * 0.7), 0.4 + 0.3 * math.sin(i))
  local v1, v2, v3 = unit(math.cos(i * 2.1), 0.5, math.sin(i * 0.37))
  local u, v = float((i * 0.137) % 1), float((i * 0.291) % 1)
  x[i] = { n1, n2, n3, v1, v2, v3, u, v }
  y[i] = { 0.5 + 0.3 * math.sin(11 * u) * n3, 0.4 + 0.2 * v1 * v, 0.3 + 0.2 * math.cos(7 * v) }
end
-- 16 rows, 8 training: one minibatch of every training row per epoch, so the order does not matter
local data = sn.dataset { x = { unpack(x, 1, 16) }, y = { unpack(y, 1, 16) }, split = 0.5, seed = 2,
                          input_names = { "normal", "view", "uv" } }

local function max_abs(a, b)
  assert(#a == #b, ("%d numbers against %d"):format(#a, #b))
  local m = 0
  for i = 1, #a do m = math.max(m, math.abs(a[i] - b[i])) end
  return m
end

local function make(enc, seed)
  return sn.mlp { inputs = { "normal", "view", "uv" }, encoding = enc, hidden = { 8, 6 }, outputs = 3, seed = seed }
end

for k, enc in ipairs(cases) do
  local net = make(enc, k)
  local label = tostring(net)
  -- what the first layer reads: the twins against the Lua reference
  local width = net:spec().encoded_inputs
  for i = 1, #x do
    local want, got = encoding.encode(net, x[i]), net:encode(x[i])
    assert(#want == width, label .. ": encoded width")
    -- (oneblob's reference integrates numerically: within 1e-11)
    assert(max_abs(got, want) < 1e-10, ("%s: net:encode row %d off by %g"):format(label, i, max_abs(got, want)))
  end
  -- net:forward (a compute shader, float) against the reference in double
  local outs, worst = net:forward(x), 0
  for i = 1, #x do worst = math.max(worst, max_abs(outs[i], forward(net, x[i]))) end
  assert(worst < 1e-5, ("%s: net:forward vs the reference: %g"):format(label, worst))

  -- two steps, both backends, against central differences of the reference (eps = 1: each step
  -- is about lr * g, so the comparison sees every gradient's size)
  local p0 = net:params()
  local rows = {}
  for i = 1, 8 do rows[i] = { data:row("train", i) } end
  local function loss(q) return reference.loss(net, rows, q) end
  local lr, eps = 0.1, 1
  local p = reference.adam_steps(net, rows, 2, { lr = lr, eps = eps })
  local moved = max_abs(p, p0)
  assert(moved > 1e-3, label .. ": two steps moved the parameters: " .. moved)
  for _, backend in ipairs { "cpu", "gl" } do
    local copy = net:clone()
    local r = sn.train { nets = copy, data = data, epochs = 2, batch = 8, adam = { lr = lr, eps = eps }, backend = backend }[1]
    assert(r.steps == 2 and math.abs(r.train_loss[1] - loss(p0)) < 1e-6 * loss(p0),
           ("%s on %s: the same rows and forward pass (%g vs %g)"):format(label, backend, r.train_loss[1], loss(p0)))
    local off = max_abs(copy:params(), p)
    assert(off < 1e-5, ("%s on %s: two steps vs the central-difference reference: %g"):format(label, backend, off))
    assert(tostring(copy) == label)
  end
  print(("%s: encode, forward (%.1g) and two steps on cpu and gl match the reference"):format(label, worst))

  -- checkpoints keep the encodings
  local path = sn.fs.tempdir("test_mlp_encoding") .. "/net.snmlp"
  net:save(path)
  local back = sn.load(path)
  assert(tostring(back) == label, tostring(back))
  assert(max_abs(back:forward(x[3]), outs[3]) == 0, label .. ": the loaded network computes the same")
end

-- net:spec() and tostring
local net = sn.mlp { inputs = { "normal", "view", "uv" }, encoding = { uv = { "frequency", bands = 8 }, normal = { "sh", degree = 4 } },
                     hidden = { 32, 32 }, outputs = 3 }
assert(tostring(net) == "mlp(8 -> 32x2 -> 3, tanh; normal: sh 4, uv: frequency 8 -> 53 inputs)", tostring(net))
local s = net:spec()
assert(s.inputs == 8 and s.encoded_inputs == 53 and net.layers[1].inputs == 53)
assert(s.encoding.uv[1] == "frequency" and s.encoding.uv.bands == 8 and s.encoding.uv.include_input == true)
assert(s.encoding.normal[1] == "sh" and s.encoding.normal.degree == 4 and s.encoding.view == nil)
assert(table.concat(net:inputs(), " ") == "normal view uv")
assert(table.concat(sn.encoding.names(), " ") == "identity frequency oneblob sh triangle_wave polynomial")
-- the same network from a count and input_names
local again = sn.mlp { inputs = 8, input_names = { "normal", "view", "uv" }, hidden = { 32, 32 },
                       encoding = { uv = { "frequency", bands = 8 }, normal = "sh" } }
assert(tostring(again) == tostring(net))

-- rendering: the fragment shader against the reference at covered pixels
local scene = sn.scene { mesh = "meshes/test_blob.glb", size = { 48, 32 }, views = { count = 1, elevation = 15 } }
local g = scene:gbuffer { view = 1, attributes = { "uv", "normal", "view" } }
local normals, views, uvs = g:read("normal"), g:read("view"), g:read("uv")
local w, h = g:size()
for k, enc in ipairs(cases) do
  local shown = make(enc, 10 + k)
  shown.layers[3].bias = { 0.4, 0.5, 0.6 }
  local img, checked, rworst = shown:render(g), 0, 0
  for py = 1, h do
    for px = 1, w do
      local n = normals:get(px, py)
      if n[4] > 0.5 then
        local vv, uv, c = views:get(px, py), uvs:get(px, py), img:get(px, py)
        local out = forward(shown, { n[1], n[2], n[3], vv[1], vv[2], vv[3], uv[1], uv[2] })
        for i = 1, 3 do rworst = math.max(rworst, math.abs(c[i] - out[i])) end
        checked = checked + 1
      end
    end
  end
  assert(checked > 100 and rworst < 1e-5, ("%s render: %d pixels, worst %g"):format(tostring(shown), checked, rworst))
end
print("render matches the reference for every case")

-- The frequency encoding's zeros are exact in the shader: sin(pi t) at integer t and cos(pi t)
-- at half-integer t are 0, as the double twin gives (to 1e-16). They were 8.7e-8 and -4.4e-8
-- (pi is not a float), which a network trained on such inputs turned into weight changes the
-- cpu backend, training on the twin's values, did not make.
local probe = sn.mlp { inputs = { "uv" }, hidden = { 8 }, outputs = 8, activation = "relu",
                       output_activation = "linear", encoding = { uv = { "frequency", bands = 2, include_input = false } } }
local identity = {}
for i = 1, 8 do identity[i] = {} for j = 1, 8 do identity[i][j] = i == j and 1 or 0 end end
probe.layers[1].weight, probe.layers[1].bias = identity, { 0, 0, 0, 0, 0, 0, 0, 0 }
probe.layers[2].weight, probe.layers[2].bias = identity, { 0, 0, 0, 0, 0, 0, 0, 0 }
-- u = 1 and 0.5, v = -1.5 and 0: features sin(pi u), cos(pi u), sin(2 pi u), cos(2 pi u), then v's.
for _, x in ipairs { { 1, -1.5 }, { 0.5, 0 }, { -2, 0.25 } } do
  local e, f = probe:encode(x), probe:forward(x)
  for i = 1, 8 do
    local want = math.max(e[i], 0)  -- relu of the twin's value
    if math.abs(want) < 1e-12 then
      assert(f[i] == 0, ("frequency feature %d at {%g, %g}: %.3g in the shader, %.3g in the twin"):format(i, x[1], x[2], f[i], e[i]))
    else
      assert(math.abs(f[i] - want) < 1e-6, ("feature %d at {%g, %g}: %g vs %g"):format(i, x[1], x[2], f[i], want))
    end
  end
end
print("ok")

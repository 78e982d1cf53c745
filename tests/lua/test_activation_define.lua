-- sn.activation.define: softsign defined by a user (GLSL + Lua twins). Its derivative against
-- central differences; two training steps on each backend (gl: the GLSL; cpu: the GLSL translated)
-- against a Lua reference that takes its gradients by central differences of the Lua twin; both
-- renderers against the Lua twin; a definition whose GLSL does not translate, refused by the cpu
-- backend with the reason; checkpoints that carry the definition; the names sn.mlp then accepts.
local sn = require "shadenet"
local reference = require "reference_forward"
local forward = reference.forward

local function softsign(x) return x / (1 + math.abs(x)) end
local function softsign_grad(x) return 1 / ((1 + math.abs(x)) * (1 + math.abs(x))) end
reference.custom.softsign = softsign
sn.activation.define {
  name = "softsign",
  glsl = "x / (1.0 + abs(x))",
  grad = "1.0 / ((1.0 + abs(x)) * (1.0 + abs(x)))",
  lua = softsign,
  lua_grad = softsign_grad,
}
-- the twin's derivative against central differences
for x = -5.03, 5, 0.1 do
  local h = 1e-6
  local fd = (softsign(x + h) - softsign(x - h)) / (2 * h)
  assert(math.abs(fd - softsign_grad(x)) < 1e-8, ("softsign' at %g: %g vs %g"):format(x, softsign_grad(x), fd))
end
local hidden = sn.activation.names("hidden")
assert(hidden[#hidden] == "softsign", "the new name is valid: " .. table.concat(hidden, ", "))
assert(sn.activation.names("output")[1] == "linear")

-- 16 rows, 8 training: one minibatch of every training row per epoch, so the order does not matter
local x, y = {}, {}
for i = 1, 16 do
  local a, b = math.sin(i * 1.7), math.cos(i * 0.9)
  x[i] = { a, b, a * b, 0.3, -a, 0.8 * b }
  y[i] = { 0.5 + 0.4 * a * b, 0.4 + 0.3 * a, 0.2 - 0.1 * b }
end
local data = sn.dataset { x = x, y = y, split = 0.5, seed = 4 }
local net = sn.mlp { inputs = 6, hidden = { 8, 8 }, outputs = 3, activation = "softsign", output_activation = "softsign", seed = 3 }
assert(tostring(net) == "mlp(6 -> 8x2 -> 3, softsign, out softsign)", tostring(net))
local p0 = net:params()

-- the Lua reference: loss = mean squared error over the training rows, gradient by central
-- differences of it, Adam as docs/lua-api/networks.md writes it. eps = 1 makes each step about
-- lr * g (not lr * sign g), so that the comparison sees every gradient's size.
local rows = {}
for i = 1, 8 do rows[i] = { data:row("train", i) } end
local lr, eps = 0.1, 1
local p = reference.adam_steps(net, rows, 2, { lr = lr, eps = eps })
local function loss(q) return reference.loss(net, rows, q) end
for _, backend in ipairs { "gl", "cpu" } do
  net:set_params(p0)
  local r = sn.train { nets = net, data = data, epochs = 2, batch = 8, adam = { lr = lr, eps = eps }, backend = backend }[1]
  assert(r.backend == backend, r.backend)
  assert(r.steps == 2 and math.abs(r.train_loss[1] - loss(p0)) < 1e-6 * loss(p0), backend .. ": the same rows and forward pass")
  local got, worst, moved = net:params(), 0, 0
  for j = 1, #p do
    worst = math.max(worst, math.abs(got[j] - p[j]))
    moved = math.max(moved, math.abs(p[j] - p0[j]))
  end
  assert(moved > 1e-3, "two steps moved the parameters: " .. moved)
  assert(worst < 1e-6, ("%s after two steps vs the central-difference reference: %g"):format(backend, worst))
  print(("softsign: two %s steps moved parameters up to %.2g; vs the central-difference reference: %.2g"):format(backend, moved,
                                                                                                              worst))
  assert(#r.dead_units == 2, "dead-unit figures of both hidden layers, counted by the cpu kernels")
end

-- GLSL that does not translate for the cpu backend (a loop): gl only, and the cpu backend says why
local function wobble(t) return t + 0.1 * math.sin(t) end
sn.activation.define {
  name = "wobble2",
  glsl = "vec4 s = x; for (int i = 0; i < 2; i++) s = s + 0.1 * sin(s); return s;",
  grad = "vec4 s = x; vec4 d = vec4(1.0);\nfor (int i = 0; i < 2; i++) { d = d * (1.0 + 0.1 * cos(s)); s = s + 0.1 * sin(s); }\nreturn d;",
  lua = function(t) return wobble(wobble(t)) end,
  lua_grad = function(t) return (1 + 0.1 * math.cos(t)) * (1 + 0.1 * math.cos(wobble(t))) end,
}
local looped = sn.mlp { inputs = 6, hidden = { 8 }, outputs = 3, activation = "wobble2", seed = 3 }
local ok, err = pcall(sn.train, { nets = looped, data = data, epochs = 1, batch = 8, backend = "cpu" })
assert(not ok and tostring(err):find("activation 'wobble2' is a definition without cpu code (its glsl, line 1: 'for' is not " ..
                                     "translated for the cpu backend", 1, true)
       and tostring(err):find(': train it with backend = "gl"', 1, true), tostring(err))
assert(sn.train { nets = looped, data = data, epochs = 1, batch = 8 }[1].backend == "gl", "auto picks gl for it")

-- rendering: the fragment shader against the Lua twin
local scene = sn.scene { mesh = "meshes/test_blob.glb", size = { 48, 32 }, views = { count = 1, elevation = 15 } }
local g = scene:gbuffer { view = 1, attributes = { "normal", "view" } }
local shown = sn.mlp { inputs = 6, hidden = { 8, 8 }, outputs = 3, activation = "softsign", seed = 7,
                       input_names = { "normal", "view" } }
shown.layers[3].bias = { 0.4, 0.5, 0.6 }
local normals, views = g:read("normal"), g:read("view")
local w, h = g:size()
for _, backend in ipairs { "gl", "cpu" } do
  local img = shown:render(g, { backend = backend })
  local checked, rworst = 0, 0
  for py = 1, h do
    for px = 1, w do
      local n = normals:get(px, py)
      if n[4] > 0.5 then
        local vv, c = views:get(px, py), img:get(px, py)
        local out = forward(shown, { n[1], n[2], n[3], vv[1], vv[2], vv[3] })
        for k = 1, 3 do rworst = math.max(rworst, math.abs(c[k] - out[k])) end
        checked = checked + 1
      end
    end
  end
  assert(checked > 100 and rworst < 2e-5, ("render (%s): %d pixels, worst %g"):format(backend, checked, rworst))
end

-- GLSL that ends in a // comment (the body's closing text starts on a line of its own): its
-- forward pass against the twin on gl, and one epoch on each backend (cpu: the comment skipped
-- by the translation) to the same parameters
sn.activation.define { name = "halved", glsl = "0.5 * x  // half", grad = "vec4(0.5) // constant",
                       lua = function(t) return 0.5 * t end, lua_grad = function() return 0.5 end }
reference.custom.halved = function(t) return 0.5 * t end
local halved = sn.mlp { inputs = 6, hidden = { 4 }, outputs = 3, activation = "halved", output_activation = "halved", seed = 2 }
local got, want = halved:forward(x[1]), forward(halved, x[1])
for o = 1, 3 do assert(math.abs(got[o] - want[o]) < 1e-6, ("halved output %d: %.7f, want %.7f"):format(o, got[o], want[o])) end
local trained = {}
for _, backend in ipairs { "gl", "cpu" } do
  local h = halved:clone()
  sn.train { nets = { h }, data = data, epochs = 1, batch = 8, backend = backend }
  trained[backend] = h:params()
end
for i = 1, #trained.gl do
  assert(math.abs(trained.gl[i] - trained.cpu[i]) < 1e-6, ("halved parameter %d: gl %.7f, cpu %.7f"):format(i, trained.gl[i], trained.cpu[i]))
end

-- checkpoints carry the definition; a different definition of the name is an error
local path = sn.fs.tempdir("test_activation_define") .. "/net.snmlp"
net:save(path)
local back = sn.load(path)
assert(tostring(back) == tostring(net) and back:params()[5] == net:params()[5])
sn.activation.define { name = "softsign", glsl = "x / (1.0 + abs(x))", grad = "1.0 / ((1.0 + abs(x)) * (1.0 + abs(x)))",
                       lua = softsign, lua_grad = softsign_grad }  -- the same again: fine
sn.activation.define { name = "softsign", glsl = "x / (2.0 + abs(x))", grad = "2.0 / ((2.0 + abs(x)) * (2.0 + abs(x)))",
                       lua = function(t) return t / (2 + math.abs(t)) end,
                       lua_grad = function(t) return 2 / ((2 + math.abs(t)) * (2 + math.abs(t))) end }
ok, err = pcall(sn.load, path)
assert(not ok and tostring(err):find("activation 'softsign' is defined differently from the network's"), tostring(err))
print("ok")

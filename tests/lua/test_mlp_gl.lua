-- The gl side from Lua: net:forward over tables, buffers and datasets against a double-precision
-- forward written here; sn.train{backend = "gl"} on a scene's dataset against the cpu backend;
-- "auto" keeps to the cpu on llvmpipe; bad input is a clear error.
local sn = require "shadenet"

local forward = require("reference_forward").forward

local function near(a, b, tol, what)
  assert(#a == #b, what .. ": lengths " .. #a .. " and " .. #b)
  for i = 1, #a do
    assert(math.abs(a[i] - b[i]) <= tol, ("%s[%d]: %.9g vs %.9g"):format(what, i, a[i], b[i]))
  end
end

assert(table.concat(sn.backends(), ",") == "cpu,gl", "the gl backend is registered: " .. table.concat(sn.backends(), ","))

-- forward: one sample, many samples, a buffer
local net = sn.mlp { inputs = 5, hidden = { 9, 9, 4 }, outputs = 2, activation = "tanh", output_activation = "sigmoid", seed = 4 }
local x1 = { 0.1, -0.7, 0.3, 0.9, -0.2 }
near(net:forward(x1), forward(net, x1), 1e-5, "one sample")
local rows = {}
for r = 1, 50 do rows[r] = { math.sin(r), math.cos(r), r / 50, -r / 70, 0.5 } end
local many = net:forward(rows)
assert(#many == 50, "one output row per sample")
for r = 1, 50, 7 do near(many[r], forward(net, rows[r]), 1e-5, "sample " .. r) end
local flat = {}
for r = 1, 50 do for i = 1, 5 do flat[#flat + 1] = rows[r][i] end end
local out = net:forward(sn.buffer { type = "float32", data = flat })
assert(out:size() == 100, "50 rows x 2 outputs")
local y = out:download()
near({ y[13], y[14] }, many[7], 0, "buffer row 7 = table row 7")

-- a scene's dataset: Phong over a blob, trained on gl and on cpu
local scene = sn.scene { mesh = "meshes/test_blob.glb", size = { 64, 48 }, views = { count = 3, elevation = 20 } }
local data = scene:dataset { inputs = { "normal", "view" }, target = sn.lighting.phong {}, split = 0.8, seed = 3 }
local ntrain, nval = data:counts()
assert(ntrain > 900 and nval > 200, "rows " .. ntrain .. " / " .. nval)
local function fresh() return sn.mlp { inputs = 6, hidden = { 8, 8, 8 }, seed = 5 } end
local a, b = fresh(), fresh()
local settings = { epochs = 3, batch = 8, adam = { lr = 3e-3 }, seed = 9 }
local function train(nets, backend)
  return sn.train { nets = nets, data = data, epochs = settings.epochs, batch = settings.batch, adam = settings.adam,
                    seed = settings.seed, backend = backend }
end
local rg = train({ a }, "gl")[1]
local rc = train({ b }, "cpu")[1]
assert(rg.backend == "gl" and rc.backend == "cpu", "backends " .. rg.backend .. ", " .. rc.backend)
assert(rg.device:find("llvmpipe") or rg.device:find("OpenGL"), "device names the GL renderer: " .. rg.device)
assert(#rg.val_mse == 3 and rg.steps == 3 * math.floor(ntrain / 8), "steps " .. rg.steps)
for e = 1, 3 do
  -- same seed, same shuffles, float on both sides: curves within 1% (see docs/lua-api/networks-gl.md)
  assert(math.abs(rg.val_mse[e] - rc.val_mse[e]) <= 0.01 * rc.val_mse[e],
         ("epoch %d: gl %.6g vs cpu %.6g"):format(e, rg.val_mse[e], rc.val_mse[e]))
end
assert(rg.val_mse[3] < 0.5 * rg.val_mse[1] or rg.val_mse[3] < 2e-3, "it learns: " .. rg.val_mse[1] .. " -> " .. rg.val_mse[3])
assert(table.concat(a:inputs(), ",") == "normal,view", "training names the inputs")

-- net:forward(dataset) evaluates the validation rows: their MSE is the last val_mse
local vo = a:forward(data):download()
local se = 0
for r = 1, nval do
  local _, yr = data:row("val", r)
  for k = 1, 3 do se = se + (vo[(r - 1) * 3 + k] - yr[k]) ^ 2 end
end
local mse = se / (nval * 3)
assert(math.abs(mse - rg.val_mse[3]) <= 1e-6 * rg.val_mse[3] + 1e-12, ("forward(dataset) mse %.9g vs val_mse %.9g"):format(mse, rg.val_mse[3]))
assert(a:forward(data, "train"):size() == ntrain * 3, "the training rows on request")

-- the trained network renders close to the truth it learned
local truth = scene:render(sn.lighting.phong {}, { view = 1 })
local img = scene:render(a, { view = 1 })
local err = sn.image.mse(truth, img)
assert(err < 4 * rg.val_mse[3] + 1e-4, "render error " .. err .. " vs val " .. rg.val_mse[3])

-- auto: llvmpipe is a software renderer, where the native cpu backend is faster
if sn.gl_info().software then
  local r = sn.train { nets = fresh(), data = data, epochs = 1, backend = "auto" }[1]
  assert(r.backend == "cpu", "auto chose " .. r.backend)
end

local function fails(pattern, f)
  local ok, e = pcall(f)
  assert(not ok, "expected an error matching " .. pattern)
  assert(tostring(e):find(pattern), "error was: " .. tostring(e))
end
fails("5 numbers expected, got 1", function() net:forward({ 1 }) end)
fails("not whole rows of 5 inputs", function() net:forward(sn.buffer { type = "float32", size = 7 }) end)
fails("dataset has 6 inputs", function() net:forward(data) end)
fails("unknown dataset set 'test'", function() a:forward(data, "test") end)
fails("a Buffer, a Dataset or a table of samples expected", function() net:forward(3) end)

-- llvmpipe's loop budget (65,535 iterations per invocation): mlp_eval.comp checks after its last
-- loop whether any was cut. With an activation that loops (tests/lua/slow_identity.lua) one layer
-- of 4 units is right; eight layers of 8 make net:forward an error naming the network instead of
-- numbers from loops stopped after a pass, and training one on gl an error that does not send it
-- to the cpu backend, which has no code for the activation.
require "slow_identity"
local slow = sn.mlp { inputs = 6, hidden = { 4 }, activation = "slow_identity", seed = 1 }
local x = { 0.1, 0.2, 0.3, 0.4, 0.5, 0.6 }
near(slow:forward(x), forward(slow, x), 1e-5, "slow_identity 6 -> 4 -> 3")
if sn.gl_info().software then
  slow = sn.mlp { inputs = 6, hidden = { 8, 8, 8, 8, 8, 8, 8, 8 }, activation = "slow_identity", seed = 1 }
  fails("mlp%(6 %-> 8x8 %-> 3, slow_identity%): one forward pass needs more loop iterations than this GL driver",
        function() slow:forward(x) end)
  local rows = sn.dataset.sample { target = sn.lighting.phong {}, n = 64, seed = 1 }
  fails("one forward pass needs more loop iterations than this GL driver runs per shader invocation.-use a smaller "
        .. "network or an activation without a long loop %(activation 'slow_identity' is a definition without cpu code",
        function() sn.train { nets = slow, data = rows, epochs = 1, backend = "gl" } end)
end
print("ok")

-- A network holds the activation and the encodings it was built with, as a Lighting value holds
-- its model: defining their names again (an edited formula saved in live mode, where sn.keep keeps
-- networks across re-runs) changes what new networks compute, never what one built before
-- computes, renders or trains to, on either backend (gl shaders, cpu kernels and twins).
local sn = require "shadenet"

local function scaled(k)
  sn.activation.define { name = "rd_scaled", glsl = ("x * %.2f"):format(k), grad = ("vec4(%.2f)"):format(k),
                         lua = function(x) return x * k end, lua_grad = function() return k end }
end
local function dbl(k)
  sn.encoding.define { name = "rd_dbl", outputs = function(w) return w end, glsl = ("return %.1f * x[j];"):format(k),
                       lua = function(x) local o = {} for i = 1, #x do o[i] = k * x[i] end return o end }
end
local function count(list, name)
  local n = 0
  for _, v in ipairs(list) do n = n + (v == name and 1 or 0) end
  return n
end
local function same(a, b, what)
  assert(#a == #b, what .. ": lengths")
  for i = 1, #a do assert(a[i] == b[i], ("%s: [%d] %.9g vs %.9g"):format(what, i, a[i], b[i])) end
end

scaled(0.5)
dbl(2)
local spec = { inputs = { "normal", "view" }, hidden = { 6, 6 }, activation = "rd_scaled", seed = 1, encoding = { view = "rd_dbl" } }
local net = sn.mlp(spec)
local row = { 0, 1, 0, 0.6, 0.8, 0 }
local forward, encoded = net:forward(row), net:encode(row)
assert(encoded[4] == 1.2, "encoded by the first definition: " .. encoded[4])
local data = sn.dataset.sample { target = sn.lighting.phong {}, n = 200, seed = 1 }
local function trained(backend)
  local copy = net:clone()
  return sn.train { nets = copy, data = data, epochs = 2, batch = 8, backend = backend, seed = 1 }[1].val_mse
end
local reference = { cpu = trained("cpu"), gl = trained("gl") }
local scene = sn.scene { mesh = sn.mesh.sphere {}, size = { 24, 24 }, views = { count = 1 } }
local gb = scene:gbuffer { view = 1, attributes = { "normal", "view" } }
local rendered = { gl = net:render(gb, { backend = "gl" }), cpu = net:render(gb, { backend = "cpu" }) }

-- Both names defined again with other formulas.
scaled(0.25)
dbl(3)
same(net:forward(row), forward, "net:forward of the network built before")
same(net:encode(row), encoded, "net:encode of the network built before")
for _, backend in ipairs { "cpu", "gl" } do
  same(trained(backend), reference[backend], backend .. " training of the network built before")
  assert(sn.image.mse(net:render(gb, { backend = backend }), rendered[backend]) == 0, backend .. " render of the network built before")
end

-- A network built now takes the new definitions.
local new = sn.mlp(spec)
assert(new:encode(row)[4] == 3 * 0.6, "encoded by the new definition")
same(new:params(), net:params(), "the same initial weights")
assert(math.abs(new:forward(row)[1] - forward[1]) > 1e-6, "a new network computes with the new activation")
assert(count(sn.activation.names("hidden"), "rd_scaled") == 1 and count(sn.encoding.names(), "rd_dbl") == 1,
       "each name is listed once")

-- The checkpoint of the network built before records its own definitions: loading it while the
-- names mean others is refused, as it was.
local path = "out/redefine_networks.snmlp"
os.execute("mkdir -p out")
net:save(path)
local ok, err = pcall(sn.load, path)
assert(not ok and err:find("is defined differently from the network's", 1, true), tostring(err))
scaled(0.5)
dbl(2)
local loaded = sn.load(path)
same(loaded:forward(row), forward, "the checkpoint once the names mean its definitions again")
print("ok")

-- The two ways a network renders over a G-buffer draw the same picture: the fragment shader
-- (backend = "gl") and the cpu kernels over the covered pixels (backend = "cpu") agree within
-- 1e-5 per channel (relative, where an exponential output is large) on real meshes, for several
-- architectures, every built-in activation and colour space, a conditioned network, into an
-- Image or into a Target; coverage and background are identical. "auto" picks the cpu kernels on
-- a software renderer and the fragment shader for a GLSL-only activation, and says why.
local sn = require "shadenet"

local function fails(pattern, f)
  local ok, err = pcall(f)
  assert(not ok, "expected an error matching " .. pattern)
  assert(tostring(err):find(pattern), "error was: " .. tostring(err))
end

-- Per channel |gl - cpu| over every pixel; alpha must match exactly, NaN/Inf at the same pixels.
local function compare(a, b, label)
  local w, h = a:size()
  local worst, covered = 0, 0
  for y = 1, h do
    for x = 1, w do
      local p, q = a:get(x, y), b:get(x, y)
      assert(p[4] == q[4], ("%s: alpha at %d,%d: %g vs %g"):format(label, x, y, p[4], q[4]))
      if p[4] > 0 then covered = covered + 1 end
      for k = 1, 3 do
        if p[k] ~= p[k] or q[k] ~= q[k] or math.abs(p[k]) == math.huge or math.abs(q[k]) == math.huge then
          assert(tostring(p[k]) == tostring(q[k]), ("%s: %s vs %s at %d,%d"):format(label, p[k], q[k], x, y))
        else
          worst = math.max(worst, math.abs(p[k] - q[k]) / math.max(1, math.abs(p[k])))
        end
      end
    end
  end
  return worst, covered
end

local function both(net, g, label, opts)
  local o = {}
  for k, v in pairs(opts or {}) do o[k] = v end
  o.backend = "gl"
  local a = net:render(g, o)
  assert(sn.render_info().backend == "gl")
  o.backend = "cpu"
  local b = net:render(g, o)
  local info = sn.render_info()
  assert(info.backend == "cpu" and info.reason == "requested", label .. ": " .. info.backend)
  assert(info.read_ms >= 0 and info.network_ms > 0, label .. ": the cpu backend times its stages")
  local worst, covered = compare(a, b, label)
  assert(covered > 500, label .. ": covered " .. covered)
  assert(worst <= 1e-5, ("%s: worst |gl - cpu| = %g"):format(label, worst))
  return worst, a, b
end

local cloth = sn.scene { mesh = "meshes/cloth.glb", size = { 96, 80 }, views = { count = 3, elevation = 25 } }
local blob = sn.scene { mesh = "meshes/test_blob.glb", size = { 120, 90 }, views = { count = 3, elevation = -10 } }
local attrs = { "normal", "view" }
local gbuffers = {
  { "cloth view 1", cloth:gbuffer { view = 1, attributes = attrs } },
  { "cloth view 3", cloth:gbuffer { view = 3, attributes = { "view", "normal" } } },
  { "blob view 2", blob:gbuffer { view = 2, attributes = attrs } },
}

-- Architectures (layers x widths, hidden activation, output activation, colour space), on
-- each mesh. Output biases keep the colours ordinary in each space.
local cases = {
  { hidden = { 4, 4, 4, 4 } },
  { hidden = { 8, 8, 8, 8, 8, 8, 8, 8 } },
  { hidden = { 13, 13, 13, 13, 6, 6, 6, 6 }, color = "hsv" },
  { hidden = { 16, 16 }, activation = "relu", color = "cie" },
  { hidden = { 64 }, activation = "sigmoid", color = "cie_xyz" },
  { hidden = { 12, 3, 12 }, activation = "leaky_relu", slope = 0.1 },
  { hidden = { 8, 8 }, activation = "sine", omega = 30, init = "siren" },
  { hidden = { 8, 8 }, activation = "softplus", output_activation = "softplus" },
  { hidden = { 8, 8 }, activation = "squareplus", output_activation = "sigmoid" },
  { hidden = { 8, 8 }, activation = "elu", alpha = 0.5, output_activation = "tanh" },
  { hidden = { 8, 8 }, activation = "gelu" },
  { hidden = { 8, 8 }, activation = "swish", output_activation = "relu" },
  { hidden = { 8 }, activation = "exponential", output_activation = "exponential" },
}
for i, c in ipairs(cases) do
  local net = sn.mlp { inputs = 6, hidden = c.hidden, outputs = 3, activation = c.activation or "tanh",
                       output_activation = c.output_activation, slope = c.slope, omega = c.omega, alpha = c.alpha,
                       init = c.init, color = c.color, seed = i, input_names = attrs }
  local bias = ({ cie = { 0.5, 0.5, 0.5 }, cie_xyz = { 0.3, 0.3, 0.3 } })[c.color] or { 0.4, 0.5, 0.6 }
  net.layers[#net.layers].bias = bias
  local g = gbuffers[(i - 1) % #gbuffers + 1]
  local worst = both(net, g[2], tostring(net) .. " on " .. g[1])
  print(("%-50s %-13s |gl - cpu| <= %.2g"):format(tostring(net), g[1], worst))
end

-- Input encodings: the cpu path encodes each pixel's inputs as the trainers encode rows.
local encoded = {
  { normal = { "sh", degree = 4 }, view = { "frequency", bands = 4 } },
  { normal = { "oneblob", bins = 8 }, view = { "triangle_wave", bands = 3 } },
  -- the last attribute unread (degree 1 is the constant alone): the shader compiler trims its
  -- texture from the array of attributes, which the gl backend refused to set
  { view = { "sh", degree = 1 } },
}
for i, enc in ipairs(encoded) do
  local net = sn.mlp { inputs = attrs, encoding = enc, hidden = { 8, 8 }, outputs = 3, seed = 20 + i }
  net.layers[#net.layers].bias = { 0.4, 0.5, 0.6 }
  local g = gbuffers[i][2]
  local worst = both(net, g, tostring(net) .. " on " .. gbuffers[i][1])
  print(("%-50s %-13s |gl - cpu| <= %.2g"):format(tostring(net), gbuffers[i][1], worst))
end

-- "auto": the cpu kernels on llvmpipe, saying so; the fragment shader where asked for storage
-- weights; the image is the cpu one.
local net = sn.mlp { inputs = 6, hidden = { 8, 8 }, outputs = 3, seed = 9, input_names = attrs }
local g = gbuffers[1][2]
local auto = net:render(g)
local info = sn.render_info()
if sn.gl_info().renderer:find("llvmpipe") then
  assert(info.backend == "cpu" and info.reason:find("software renderer"), info.backend .. ": " .. info.reason)
else
  assert(info.backend == "gl" and info.reason:find("hardware GPU"), info.backend .. ": " .. info.reason)
end
assert(info.nonfinite == 0, "a finite network draws no NaN")
assert(sn.image.mse(auto, net:render(g, { backend = info.backend })) == 0, "auto draws what it names")
net:render(g, { weights = "storage" })
assert(sn.render_info().backend == "gl" and sn.render_info().reason:find("storage"), sn.render_info().reason)
-- frames > 1 renders again into the same image: the same picture
assert(sn.image.mse(net:render(g, { backend = "cpu", frames = 3 }), net:render(g, { backend = "cpu" })) == 0)
fails("unknown net:render option 'backend' 'vulkan' %(valid: auto, gl, cpu%)", function()
  net:render(g, { backend = "vulkan" })
end)
fails("weights = \"storage\" is a choice of the gl backend", function()
  net:render(g, { backend = "cpu", weights = "storage" })
end)

-- Into a Target (what the live window shows): no image on the host; pixels the previous frame
-- drew outside this mesh's box are cleared; the same picture as the Image.
for _, backend in ipairs { "gl", "cpu" } do
  local w, h = g:size()
  local target = sn.target { width = w, height = h }
  target:clear { 0.3, 0.2, 0.1, 1 }  -- stale colour everywhere
  local back = net:render(g, { backend = backend, target = target })
  assert(back == target, "returns the target it drew into")
  local img = net:render(g, { backend = backend })
  assert(sn.image.mse(target:read(), img) == 0, backend .. ": the target holds the Image's picture")
  local via_scene = cloth:render(net, { view = 1, backend = backend, target = target })
  assert(via_scene == target and sn.image.mse(target:read(), img) == 0, backend .. ": scene:render into the target")
  fails("the target is 5x5, the G%-buffer 96x80", function()
    net:render(g, { backend = backend, target = sn.target { width = 5, height = 5 } })
  end)
end
fails("'backend', 'target' and 'nonfinite' are a network's", function() cloth:render(sn.lighting.phong {}, { backend = "cpu" }) end)

-- A G-buffer renders again into a reused target: an earlier G-buffer still held keeps its own
-- picture, and the network drawn from each matches its own view.
local g1 = blob:gbuffer { view = 1, attributes = attrs }
local before = net:render(g1, { backend = "cpu" })
for v = 1, 3 do blob:gbuffer { view = v, attributes = attrs }:release() end
assert(sn.image.mse(net:render(g1, { backend = "cpu" }), before) == 0, "a held G-buffer is never reused")
-- A reused target only clears where its last G-buffer's meshes were: a small view drawn after a
-- close-up (whose pixels filled the frame) holds exactly what a fresh target holds.
local far = sn.camera { eye = { 0, 0.5, 9 }, target = { 0.6, 0, 0 } }
local close = sn.camera { eye = { 0, 0.3, 1.6 }, target = { 0, 0, 0 } }
local odd = sn.scene { mesh = "meshes/test_blob.glb", size = { 100, 75 } }  -- a size no other target has
local fresh = odd:gbuffer { camera = far, attributes = attrs }  -- held: the next ones get other targets
local big = odd:gbuffer { camera = close, attributes = attrs }
assert(big:covered() > 0.5 * 100 * 75, "the close-up fills the frame: " .. big:covered())
big:release()
local reused = odd:gbuffer { camera = far, attributes = attrs }  -- in the close-up's target
for _, a in ipairs(attrs) do
  assert(sn.image.mse(reused:read(a), fresh:read(a)) == 0, "stale pixels of the close-up in '" .. a .. "'")
end
assert(reused:covered() == fresh:covered())

-- NaN and Inf: an exponential output that overflows is Inf in both pictures at the same pixels,
-- and counted.
local hot = sn.mlp { inputs = 6, hidden = { 4 }, outputs = 3, output_activation = "exponential", seed = 3,
                     input_names = attrs }
hot.layers[2].bias = { 200, 0, 0 }
local a = hot:render(g, { backend = "gl" })
local covered_gl = sn.render_info().nonfinite
local b = hot:render(g, { backend = "cpu" })
local covered_cpu = sn.render_info().nonfinite
compare(a, b, "overflowing network")
assert(covered_gl > 500 and covered_gl == covered_cpu, ("nonfinite: gl %d, cpu %d"):format(covered_gl, covered_cpu))

-- A conditioned network: the condition's value reaches both backends, from `values` or the net.
local gold = sn.lighting.ggx {}
local data = blob:dataset { target = gold, vary = { roughness = { 0.1, 0.8 } }, samples = 3000,
                            inputs = { "normal", "roughness", "view" } }
local cond = sn.mlp { inputs = 7, hidden = { 8, 8, 8 }, outputs = 3, seed = 4 }
sn.train { nets = cond, data = data, epochs = 1, batch = 8 }
local gc = blob:gbuffer { view = 2, attributes = attrs }
local _, low = both(cond, gc, "conditioned, roughness 0.2", { values = { roughness = 0.2 } })
local _, mid = both(cond, gc, "conditioned, its own value")
assert(sn.image.mse(low, mid, { channels = 3 }) > 1e-8, "the condition changes the picture")

-- An activation whose GLSL does not translate for the cpu backend (softsign written with a loop):
-- auto falls back to the fragment shader and says why; asking for cpu names the activation, why
-- and the way out.
sn.activation.define { name = "softsign_r", glsl = "vec4 s = x; for (int i = 0; i < 1; i++) s = s / (1.0 + abs(s)); return s;",
                       grad = "1.0 / ((1.0 + abs(x)) * (1.0 + abs(x)))",
                       lua = function(x) return x / (1 + math.abs(x)) end,
                       lua_grad = function(x) return 1 / (1 + math.abs(x)) ^ 2 end }
local custom = sn.mlp { inputs = 6, hidden = { 8 }, outputs = 3, activation = "softsign_r", seed = 5, input_names = attrs }
custom:render(g)
info = sn.render_info()
assert(info.backend == "gl" and info.reason:find("activation 'softsign_r' is a definition without cpu code (its glsl, line 1: 'for'",
                                                 1, true), info.reason)
fails("activation 'softsign_r' is a definition without cpu code %(its glsl, line 1: 'for' .-%): render it with backend = \"gl\"", function()
  custom:render(g, { backend = "cpu" })
end)
print("ok")

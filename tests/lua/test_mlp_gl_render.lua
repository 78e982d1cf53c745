-- net:render(gbuffer): the network, drawn by each backend (the fragment shader and the cpu
-- kernels), equals a double-precision forward pass (tests/lua/reference_forward.lua) at the
-- G-buffer's covered pixels, in every colour space, with the output taken back to RGB
-- (sn.color.decode, the CPU twin); a weight edit shows in the fragment shader's next render with
-- one upload and no new program; bad networks are clear errors.
local sn = require "shadenet"

local forward = require("reference_forward").forward

local scene = sn.scene { mesh = "meshes/test_blob.glb", size = { 64, 48 }, views = { count = 2, elevation = 15 } }
local g = scene:gbuffer { view = 1, attributes = { "view", "normal" } }  -- attachment order differs from the net's
local normals, views = g:read("normal"), g:read("view")
local w, h = g:size()

local function check(net, label, backend)
  backend = backend or "gl"
  label = label .. " (" .. backend .. ")"
  local img = net:render(g, { backend = backend })
  assert(sn.render_info().backend == backend, label .. ": drawn by " .. sn.render_info().backend)
  local checked, worst = 0, 0
  for y = 1, h do
    for x = 1, w do
      local n, c = normals:get(x, y), img:get(x, y)
      if n[4] < 0.5 then
        assert(c[1] == 0 and c[2] == 0 and c[3] == 0 and c[4] == 0, label .. ": background left transparent black")
      else
        assert(c[4] == 1, label .. ": alpha = coverage")
        if (x + y) % 2 == 0 then
          local v = views:get(x, y)
          local out = forward(net, { n[1], n[2], n[3], v[1], v[2], v[3] })
          local rgb = sn.color.decode(net:spec().color, out)
          for k = 1, 3 do worst = math.max(worst, math.abs(c[k] - rgb[k])) end
          checked = checked + 1
        end
      end
    end
  end
  assert(checked > 150, label .. ": checked " .. checked)
  -- float against double; hsv and cie pass through the colour conversion too
  assert(worst < 2e-5, ("%s: worst |fragment - double twin| = %g"):format(label, worst))
  return img, worst
end

for _, case in ipairs {
  { activation = "tanh", color = "rgb", hidden = { 8, 8, 8, 8 } },
  { activation = "leaky_relu", color = "hsv", hidden = { 12, 12 }, slope = 0.2 },
  { activation = "sigmoid", color = "cie", hidden = { 13, 13, 6, 6 } },
  { activation = "relu", color = "cie_xyz", hidden = { 20, 5 } },
  -- the activations added beside the thesis' four (sine with SIREN's w0 and initialisation)
  { activation = "sine", color = "rgb", hidden = { 8, 8 }, omega = 30, init = "siren" },
  { activation = "softplus", color = "rgb", hidden = { 8, 8 }, output_activation = "softplus" },
  { activation = "squareplus", color = "rgb", hidden = { 8, 8 } },
  { activation = "elu", color = "rgb", hidden = { 8, 8 }, alpha = 0.5 },
  { activation = "gelu", color = "rgb", hidden = { 8, 8 }, output_activation = "sigmoid" },
  { activation = "swish", color = "rgb", hidden = { 8, 8 } },
  { activation = "exponential", color = "rgb", hidden = { 8 }, output_activation = "exponential" },
} do
  local net = sn.mlp { inputs = 6, hidden = case.hidden, outputs = 3, activation = case.activation,
                       slope = case.slope, omega = case.omega, alpha = case.alpha, init = case.init,
                       output_activation = case.output_activation, color = case.color, seed = 7,
                       input_names = { "normal", "view" } }
  -- Outputs near the middle of each colour space's range, so the decoded colours are ordinary.
  local L = #net.layers
  local bias = case.color == "cie" and { 0.5, 0.5, 0.5 } or { 0.4, 0.5, 0.6 }
  if case.color == "cie_xyz" then bias = { 0.3, 0.3, 0.3 } end
  net.layers[L].bias = bias
  for _, backend in ipairs { "gl", "cpu" } do
    local _, worst = check(net, tostring(net), backend)
    print(("%-45s %-3s worst error %.2g"):format(tostring(net), backend, worst))
  end
end

-- Weight edits: one upload per version, the same program, a different image that is still right.
local net = sn.mlp { inputs = 6, hidden = { 8, 8 }, outputs = 3, seed = 3, input_names = { "normal", "view" } }
local before = check(net, "before the edit")
local programs, uploads = sn.program_cache_size(), sn.mlp_weight_uploads()
check(net, "unchanged")
assert(sn.mlp_weight_uploads() == uploads, "an unchanged network is not uploaded again")
net.layers[1].weight[2][4] = 1.5
net.layers[3].bias[1] = 0.8
local after = check(net, "after the edit")
assert(sn.mlp_weight_uploads() == uploads + 1, "the edit is uploaded once")
assert(sn.program_cache_size() == programs, "a weight edit compiles nothing")
assert(sn.image.mse(before, after) > 1e-3, "the edit shows in the image")
-- the storage-buffer path (what does not fit a uniform buffer) draws the same image
assert(sn.image.mse(net:render(g, { weights = "storage", frames = 2 }), after) < 1e-12, "storage-buffer weights")

-- Errors name the problem before any GPU work.
local function fails(pattern, f)
  local ok, err = pcall(f)
  assert(not ok, "expected an error matching " .. pattern)
  assert(tostring(err):find(pattern), "error was: " .. tostring(err))
end
fails("3 outputs %(a colour%), this one has 4", function()
  sn.mlp { inputs = 6, hidden = { 4 }, outputs = 4, input_names = { "normal", "view" } }:render(g)
end)
fails("does not name the G%-buffer attributes", function() sn.mlp { inputs = 6, hidden = { 4 } }:render(g) end)
fails("uv", function() sn.mlp { inputs = 2, hidden = { 4 }, input_names = { "uv" } }:render(g) end)
fails("input_names {normal, uv} describe 5 input columns", function()  -- refused before any render
  sn.mlp { inputs = 6, hidden = { 4 }, input_names = { "normal", "uv" } }
end)
fails("frames' must be 1..100000", function() net:render(g, { frames = 0 }) end)
fails("unknown option 'frame'", function() net:render(g, { frame = 2 }) end)
fails("'uniform' %(valid: auto, storage%)", function() net:render(g, { weights = "uniform" }) end)

-- llvmpipe's loop budget (65,535 iterations per invocation): on a software renderer the fragment
-- shader reports a loop it cut. An activation that loops 10,000 times per call (the identity,
-- slowly; no cpu code, so the fragment shader draws it): one layer of 4 calls it once and draws
-- right; eight layers of 8 call it 16 times, and the render is an error, not a wrong picture
-- (before, 0.37 MSE from the same network with a loop-free identity).
require "slow_identity"
check(sn.mlp { inputs = 6, hidden = { 4 }, activation = "slow_identity", seed = 7, input_names = { "normal", "view" } },
      "slow_identity 4")
if sn.gl_info().software then
  local deep = sn.mlp { inputs = 6, hidden = { 8, 8, 8, 8, 8, 8, 8, 8 }, activation = "slow_identity", seed = 7,
                        input_names = { "normal", "view" } }
  fails("mlp%(6 %-> 8x8 %-> 3, slow_identity%): one forward pass needs more loop iterations than this GL driver",
        function() deep:render(g, { backend = "gl" }) end)
end
print("ok")

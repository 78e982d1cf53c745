-- The scene the live tests watch, edit and break. A small network is trained once through
-- sn.keep (it prints TRAINED when it does); its first-layer weights tint a lit sphere, so a
-- weight edit shows as a colour change. The truth is the same sphere in a fixed colour.
-- The tests copy this file and tint.frag into a folder of their own and rewrite the copies.
local sn = require "shadenet"
local dir = debug.getinfo(1, "S").source:match("^@(.*)/[^/]*$") or "."

local net = sn.keep("net", function()
  local xs, ys = {}, {}
  for i = 1, 400 do
    local x = {}
    for k = 1, 6 do x[k] = math.sin(i * (k + 0.5) * 0.731) end
    xs[i], ys[i] = x, { 0.5 + 0.3 * x[1], 0.5 + 0.3 * x[2] * x[3], 0.4 }
  end
  local data = sn.dataset { x = xs, y = ys, split = 0.8, seed = 1 }
  local n = sn.mlp { inputs = 6, hidden = { 8, 8 }, outputs = 3, seed = 2 }
  sn.train { nets = n, data = data, epochs = 2, batch = 8, backend = "cpu" }
  print("TRAINED " .. n:trained_steps())
  return n
end)
-- EDITS

local sphere = sn.mesh.sphere { segments = 48, rings = 24 }
local program = sn.program { vertex = "mesh.vert", fragment = dir .. "/tint.frag" }
local function shade(view, tint)
  local t = sn.target { width = view.width, height = view.height }
  sn.draw { target = t, program = program, mesh = sphere, camera = view.camera, clear = { 0, 0, 0, 0 },
            uniforms = { u_tint = tint, u_light = view.light.dir } }
  return t
end

local w = net.layers[1].weight
sn.live.show {
  network = function(view) return shade(view, { 0.5 + w[1][1], 0.5 + w[1][2], 0.5 + w[1][3] }) end,
  truth = function(view) return shade(view, { 0.8, 0.5, 0.3 }) end,
  camera = sn.camera { eye = { 0.6, 0.8, 2.6 } },
  light = { dir = { 0.5, 0.7, 0.6 } },
  title = "live test",
}

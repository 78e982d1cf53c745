-- A lighting model of your own, live: Minnaert's model in minnaert.glsl (beside this file) and
-- its Lua twin, a network trained on it once, both shown side by side.
--   build/shadenet --window --watch examples/lighting/live_model.lua
-- Edit minnaert.glsl (say, multiply by vec3(1.0, 0.6, 0.3)) and the twin below alike, and save: the
-- truth re-renders while the trained network stays. Keys 1-4: network, truth, |error|, side by side.
local sn = require "shadenet"

local minnaert = sn.lighting.define {
  name = "minnaert",
  params = { k = { default = 1.4, range = { 1, 3 } }, albedo = { type = "rgb", default = 0.9, range = { 0, 1 } } },
  glsl = "minnaert.glsl",
  twin = function(s, p)
    local nl, nv = math.max(sn.vec3.dot(s.n, s.l), 0), math.max(sn.vec3.dot(s.n, s.v), 0)
    if not (nl > 0 and nv > 0) then return { 0, 0, 0 } end
    local k = nl ^ p.k * nv ^ (p.k - 1)
    return { s.light_color[1] * p.albedo[1] * k, s.light_color[2] * p.albedo[2] * k, s.light_color[3] * p.albedo[3] * k }
  end,
}

local scene = sn.scene { mesh = "meshes/test_blob.glb", size = { 320, 320 }, views = { count = 8, elevation = 20 } }
local net = sn.keep("minnaert net", function()
  local data = scene:dataset { inputs = { "normal", "view" }, target = minnaert, seed = 1 }
  local net = sn.mlp { inputs = 6, hidden = { 16, 16, 16, 16 }, outputs = 3, seed = 1 }
  local run = sn.train { nets = net, data = data, epochs = 10, batch = 8, keep = "best" }
  print(("trained %s once: best val MSE %.3g"):format(tostring(net), run[1].best_val_mse))
  return net
end)

sn.live.show { scene = scene, network = net, truth = minnaert, mode = "side", title = "Minnaert, defined in Lua + GLSL" }

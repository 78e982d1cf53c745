-- The child of test_egl_platforms.lua: renders and trains on the EGL platform that
-- SHADENET_EGL_PLATFORM picks, saves the network's picture to arg[1] (EXR, every float bit) and
-- prints the platform, the renderer and the trained parameters (%.9g: every float bit too).
local sn = require "shadenet"
local info = sn.gl_info()
print("platform " .. info.platform)
print("renderer " .. info.renderer)

-- G-buffer pass, ground truth and dataset (GL), then the gl trainer's two kernels: 4x6 trains one
-- network per invocation on a CPU renderer, 8x8 one sample per invocation.
local scene = sn.scene { mesh = "meshes/test_blob.glb", size = { 64, 48 }, views = { count = 2, elevation = 15 } }
local data = scene:dataset { inputs = { "normal", "view" }, target = sn.lighting.phong {}, seed = 1 }
local nets = { sn.mlp { inputs = 6, hidden = { 6, 6, 6, 6 }, outputs = 3, seed = 1 },
               sn.mlp { inputs = 6, hidden = { 8, 8, 8, 8, 8, 8, 8, 8 }, outputs = 3, seed = 2 } }
local runs = sn.train { nets = nets, data = data, epochs = 2, batch = 8, backend = "gl" }
for i, net in ipairs(nets) do
  local values = { ("net %d best_val_mse %.9g"):format(i, runs[i].best_val_mse) }
  for _, v in ipairs(net:params()) do values[#values + 1] = ("%.9g"):format(v) end
  print(table.concat(values, " "))
end

-- The fragment shader's picture of the trained 8x8 network over the second view.
local g = scene:gbuffer { view = 2, attributes = { "normal", "view" } }
nets[2]:render(g, { backend = "gl" }):save(arg[1])

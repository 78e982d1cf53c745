-- Frames per second of live mode's network view: the loop's own per-frame work (sn.live._frame:
-- the G-buffer pass, the network into the loop's cached target, the mode's composition), then
-- what the loop does after it (present, a full garbage collection), for an orbiting camera.
--
--   shadenet [--window --size WxH] bench/live_view.lua [backends] [frames] [net] [mode] [size]
--     backends: gl,cpu (default both)        frames: frames timed per backend (default 60)
--     net:      hidden layers x width (default 8x8)       mode: network | side | error (default network)
--     size:     the view, WxH (default 960x720; give the window the same --size)
--
-- With --window each frame is also shown (under Xvfb the present is a copy into the X server). The network is untrained (tanh, normal + view -> RGB) on
-- meshes/test_blob.glb; the truth (for side/error) is Phong. Prints the median and the 10th/90th
-- percentile ms per frame (linear between the two nearest frames), fps from the median, and the
-- 1-minute load average.
local sn = require "shadenet"
package.path = (arg[0]:match("^(.*)/[^/]*$") or ".") .. "/?.lua;" .. package.path
local B = require "common"

local o = B.args("bench/live_view.lua", {
  { "backends", "gl,cpu", B.list(B.one_of { "gl", "cpu" }) },
  { "frames", "60", B.whole(1) },
  { "net", "8x8", B.arch },
  { "mode", "network", B.one_of { "network", "side", "error" } },
  { "size", "960x720", B.size },
})
local backends, frames, mode = o.backends, o.frames, o.mode
local layers, width = o.net[1], o.net[2]
local w, h = o.size[1], o.size[2]

local scene = sn.scene { mesh = "meshes/test_blob.glb", size = { w, h }, views = { count = 8, elevation = 20 } }
local hidden = {}
for i = 1, layers do hidden[i] = width end
local net = sn.mlp { inputs = 6, hidden = hidden, outputs = 3, seed = 1, input_names = { "normal", "view" } }
net.layers[#net.layers].bias = { 0.4, 0.5, 0.6 }
local cam = scene:views()[1]
local eye, target = cam:eye(), cam:target()
local dx, dz = eye[1] - target[1], eye[3] - target[3]
local radius, angle0 = math.sqrt(dx * dx + dz * dz), math.atan2(dx, dz)

print(("live view %dx%d, mode %s, mlp %s, %d frames per backend, %s"):format(w, h, mode, tostring(net), frames,
  sn.windowed() and "window" or "headless"))
for _, backend in ipairs(backends) do
  sn.live.show { scene = scene, network = net, truth = sn.lighting.phong {}, backend = backend, mode = mode }
  local load = B.load()
  local times = {}
  for i = 0, frames do
    local a = angle0 + i * 0.05
    local t0 = sn.clock()
    local out = sn.live._frame { mode = mode, width = w, height = h, fov = cam:fov(), target = target,
                                 eye = { target[1] + radius * math.sin(a), eye[2], target[3] + radius * math.cos(a) } }
    sn.present(out)
    sn.finish()
    collectgarbage()  -- as the loop does after every frame
    if i > 0 then times[#times + 1] = (sn.clock() - t0) * 1e3 end  -- frame 0 compiles
  end
  local med = B.median(times)
  print(("%-4s %7.2f ms/frame median (p10 %.2f, p90 %.2f) = %5.1f fps   load %s   (%s)"):format(backend, med,
    B.quantile(times, 0.1), B.quantile(times, 0.9), 1000 / med, load, sn.render_info().reason))
end

-- Live mode without a display: sn.keep across re-runs, sn.live.show/render (every view, Images
-- uploaded, the heatmap equal to the figures' CPU heatmap), recordings, and `shadenet --watch`
-- headless: a module the script requires is watched, console lines from a pipe redraw.
local sn = require "shadenet"
package.path = "tests/live/?.lua;" .. package.path
local H = require "harness"
local live = sn.live

local fails = require("expect").fails

-- 1. sn.keep: made once, again when its key changes or after sn.forget.
local made = 0
local function make() made = made + 1 return { n = made } end
local a = sn.keep("t", make)
assert(sn.keep("t", make) == a and made == 1, "kept")
local b = sn.keep("t", make, { epochs = 2 })
assert(b ~= a and made == 2, "a new key makes it again")
assert(sn.keep("t", make, { epochs = 2 }) == b and made == 2, "an equal key keeps it")
sn.forget("t")
assert(sn.keep("t", make) ~= b and made == 3, "forgotten, made again")
fails(function() sn.keep("x", function() end) end, "sn.keep('x'): the function returned nil")
fails(function() sn.keep(1, make) end, "must be a name")
fails(function() sn.forget("nope") end, "nothing kept under 'nope' (kept: t)")

-- 2. A kept network goes back to its trained state at each run; a failed run to the last good one.
local net = sn.keep("net", function() return sn.mlp { inputs = 6, hidden = { 4 }, outputs = 3, seed = 3 } end)
local w0 = net.layers[1].weight[1][1]
live._begin_run()
net.layers[1].weight[1][1] = 0.75          -- the script's edit
live._end_run(true)                        -- a good run: the edit is the good state
live._begin_run()
assert(net.layers[1].weight[1][1] == w0, "a re-run starts from the kept weights")
net.layers[1].weight[1][1] = -0.5          -- a run that edits, then fails
live._end_run(false)
assert(math.abs(net.layers[1].weight[1][1] - 0.75) < 1e-7, "a failed run leaves the last good run's weights")

-- 3. sn.live.show and sn.live.render, with plain functions of the view.
fails(function() live.show { network = function() end, colour = 1 } end,
      "unknown option 'colour' (valid: network, truth, scene, camera, light, mode")
fails(function() live.show { network = function() end, mode = "diff" } end,
      "unknown mode 'diff' (valid: network, truth, error, side)")
fails(function() live.show { network = net } end, "give the scene it is rendered in")
local sphere = sn.mesh.sphere { segments = 32, rings = 16 }
local normals = sn.program { vertex = "mesh.vert", fragment = "normals.frag" }
local calls = 0
local function draw_normals(view)
  calls = calls + 1
  local t = sn.target { width = view.width, height = view.height }
  sn.draw { target = t, program = normals, mesh = sphere, camera = view.camera, clear = { 0, 0, 0, 0 } }
  return t
end
local function flat(view)  -- returns an Image, as scene:render does
  local img = sn.image.new { width = view.width, height = view.height, channels = 4, fill = 0 }
  local n = draw_normals(view):read()
  for y = 1, view.height do
    for x = 1, view.width do
      if n:get(x, y)[4] > 0.5 then img:set(x, y, { 0.5, 0.5, 0.5, 1 }) end
    end
  end
  return img
end
live.show { network = draw_normals, truth = flat, camera = sn.camera { eye = { 0.5, 0.6, 2.8 } }, size = { 60, 40 } }
local n_img = live.render { mode = "network" }:read()
local t_img = live.render { mode = "truth" }:read()
assert(select(1, n_img:size()) == 60, "the show's size")
assert(t_img:get(30, 20)[1] == 0.5 and t_img:get(1, 1)[4] == 0, "an Image view is uploaded as it is")
local e_img = live.render { mode = "error" }:read()
-- The heatmap equals the figures' CPU heatmap of |network - truth| (same colormap, same value).
local diff = sn.image.new { width = 60, height = 40, channels = 4, fill = 0 }
for y = 1, 40 do
  for x = 1, 60 do
    local p, q = n_img:get(x, y), t_img:get(x, y)
    diff:set(x, y, { p[1] - q[1], p[2] - q[2], p[3] - q[3], math.max(p[4], q[4]) })
  end
end
local cpu = sn.image.heatmap(diff, { max = 0.25, colorbar = false, mask = diff })
local checked = 0
for y = 1, 40, 3 do
  for x = 1, 60, 3 do
    if diff:get(x, y)[4] > 0.5 then
      local g, c = e_img:get(x, y), cpu:get(x, y)
      for k = 1, 3 do
        assert(math.abs(g[k] - c[k]) < 1e-5, ("heatmap (%d,%d) channel %d: GPU %g, CPU %g"):format(x, y, k, g[k], c[k]))
      end
      checked = checked + 1
    else
      assert(e_img:get(x, y)[4] == 0, "uncovered pixels stay transparent")
    end
  end
end
assert(checked > 30, "enough covered pixels checked: " .. checked)
local side = live.render { mode = "side", width = 90, height = 40 }
local sw, sh = side:size()
assert(sw == 90 and sh == 40, ("side by side: 2 x 2 panels of 45x20 filling the view, got %dx%d"):format(sw, sh))
fails(function() live.render { mode = "side", widht = 3 } end, "unknown option 'widht'")

-- 4. Recordings: an orbit and a weight sweep, headless; the swept value is put back.
local dir, frames = sn.record { orbit = { count = 4 }, mode = "network", dir = "out/live_tests/headless/orbit" }
assert(#frames == 4 and dir:sub(1, 1) == "/", "4 frames with absolute paths")
local f1, f3 = sn.image.load(frames[1]), sn.image.load(frames[3])
assert(sn.image.mse(f1, f3) > 1e-4, "the orbit's frames differ")
assert(sn.image.mse(f1, n_img, { channels = 3 }) < 1e-4, "the first orbit frame is the current view (8-bit PNG)")
local tint = 0.5
live.show { network = function(view)
  local t = sn.target { width = view.width, height = view.height }
  t:clear({ tint, 0, 0, 1 })
  return t
end, size = { 8, 8 } }
local _, sweep = sn.record { sweep = { set = function(v) tint = v end, get = function() return tint end,
                                       from = 0, to = 1, count = 3 }, dir = "out/live_tests/headless/sweep" }
assert(#sweep == 3 and tint == 0.5, "three frames, the value put back")
assert(math.abs(sn.image.load(sweep[2]):get(4, 4)[1] - 0.5) < 1 / 255, "frame 2 shows the middle value")
assert(sn.image.load(sweep[3]):get(4, 4)[1] == 1, "frame 3 shows the last value")

-- 5. `shadenet --watch` headless: a required module is watched; the console redraws.
local wdir = "out/live_tests/headless/watch"
os.execute(("mkdir -p %q"):format(wdir))
H.write(wdir .. "/tint.lua", "return { 0.2, 0.4, 0.6 }\n")
H.write(wdir .. "/main.lua", ([[
local sn = require "shadenet"
package.path = %q .. "/?.lua;" .. package.path
local tint = require "tint"
local runs = sn.keep("runs", function() return { n = 0 } end)
runs.n = runs.n + 1
print("RUN " .. runs.n)
sn.live.show { network = function(view)
  local t = sn.target { width = view.width, height = view.height }
  t:clear({ tint[1], tint[2], tint[3], 1 })
  return t
end, size = { 4, 4 } }
]]):format(wdir))
local s = H.start { dir = wdir .. "/session", script = wdir .. "/main.lua", window = false }
s:wait_frame(1)
assert(math.abs(s:image(1):get(2, 2)[2] - 0.4) < 1e-6, "first frame")
H.write_in_place(wdir .. "/tint.lua", "return { 0.9, 0.1, 0.6 }\n")  -- the module, saved in place
s:wait_log("RUN 2")
local n = s:settle()
assert(math.abs(s:image(n):get(2, 2)[1] - 0.9) < 1e-6, "the module's new value is shown")
s:send("tint[3] = 0.05")  -- the script's local, from the console
n = s:settle()
assert(math.abs(s:image(n):get(2, 2)[3] - 0.05) < 1e-6, "the console's edit is shown")
s:stop()
-- A network's view says which backend draws it once, not again at each reload.
local nscript = wdir .. "/net.lua"
local function net_script(run)
  return ([[
local sn = require "shadenet"
local scene = sn.scene { mesh = sn.mesh.sphere {}, size = { 16, 16 } }
sn.live.show { scene = scene, network = sn.mlp { inputs = { "normal", "view" }, hidden = { 4 } } }
print("NET RUN %d")
]]):format(run)
end
H.write(nscript, net_script(1))
local ns = H.start { dir = wdir .. "/net_session", script = nscript, window = false }
ns:wait_log("NET RUN 1")
ns:wait_frame(1)
for run = 2, 3 do
  H.write_in_place(nscript, net_script(run))
  ns:wait_log("NET RUN " .. run)
  ns:settle()
end
ns:stop()
local said = select(2, ns:log():gsub("%[live%] network view: ", ""))
assert(said == 1, ("the backend line, said %d times over 3 runs:\n%s"):format(said, ns:log()))
-- 6. Every example of docs/lua-api/live.md runs, each in a fresh process (they declare views).
local doc = H.read("docs/lua-api/live.md")
local count = 0
for body in doc:gmatch("```lua\n(.-)\n```") do
  count = count + 1
  local path = ("out/live_tests/headless/doc_%d.lua"):format(count)
  H.write(path, body .. "\nprint('DOC EXAMPLE OK')\n")
  H.run_headless(path, "DOC EXAMPLE OK")
end
assert(count >= 8, "docs/lua-api/live.md has " .. count .. " examples")
print("live headless: keep, restore, every view, heatmap = CPU heatmap, recordings, --watch with a module, " ..
      count .. " doc examples")

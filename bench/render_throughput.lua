-- Rendering throughput of networks in the fragment shader: ms per frame and ns per covered
-- fragment for 4x4, 8x8, 12x12 and 16x16 networks (hidden layers x width; tanh, inputs normal +
-- view, RGB out) at 640x480, 1280x720 and 1920x1080, printed beside the thesis' tables 4.6 and
-- 4.7 (a GTX 1060).
--
--   shadenet bench/render_throughput.lua [frames] [weights]
--     frames:  frames timed per cell (default 20)
--     weights: auto (uniform buffer where it fits, the default) | storage
--
-- The G-buffer is a unit sphere seen from 2.7 units (about 59% of the frame covered). A cell's
-- time is (t(frames + 1) - t(1)) / frames: draws only, the read-back of the image cancels out.
-- "load" is the 1-minute load average before the cell: other work on a shared machine slows it.
local sn = require "shadenet"

local frames = tonumber(arg[1] or "20")
local weights = arg[2] or "auto"

-- The 1-minute load average before a job, from the experiment scripts' library.
package.path = (arg[0]:match("^(.*)/[^/]*$") or ".") .. "/../scripts/?.lua;" .. package.path
local results = require "lib.results"
local function loadavg()
  local l = results.load_average()
  return l and tostring(l[1]) or "?"
end

-- A UV sphere of radius 1.
local function sphere(rings, segments)
  local pos, idx = {}, {}
  for r = 0, rings do
    local th = math.pi * r / rings
    for s = 0, segments do
      local ph = 2 * math.pi * s / segments
      pos[#pos + 1] = math.sin(th) * math.cos(ph)
      pos[#pos + 1] = math.cos(th)
      pos[#pos + 1] = math.sin(th) * math.sin(ph)
    end
  end
  for r = 0, rings - 1 do
    for s = 0, segments - 1 do
      local a, b = r * (segments + 1) + s + 1, (r + 1) * (segments + 1) + s + 1
      for _, i in ipairs { a, a + 1, b, a + 1, b + 1, b } do idx[#idx + 1] = i end
    end
  end
  return sn.procedural_mesh { name = "sphere", positions = pos, normals = pos, indices = idx }
end

local thesis_ms = { ["4x4"] = { 0.879, 1.697, 2.177 }, ["8x8"] = { 4.263, 8.241, 10.067 },
                    ["12x12"] = { 12.754, 24.002, 29.653 }, ["16x16"] = { 29.117, 52.655, 66.710 } }
local thesis_ns = { ["4x4"] = 15.8, ["8x8"] = 79.3, ["12x12"] = 237.3, ["16x16"] = 538.9 }
local sizes = { { 640, 480 }, { 1280, 720 }, { 1920, 1080 } }
local archs = { { 4, 4 }, { 8, 8 }, { 12, 12 }, { 16, 16 } }

local mesh = sphere(48, 96)
local info = sn.gl_info()
print(("device: %s (OpenGL %s); %d frames per cell; weights: %s"):format(info.renderer, info.version, frames, weights))

local ms, ns = {}, {}
for _, sz in ipairs(sizes) do
  local scene = sn.scene { mesh = mesh, size = sz, views = { count = 1, elevation = 0, distance = 2.7 } }
  local g = scene:gbuffer { view = 1, attributes = { "normal", "view" } }
  local covered = g:covered()
  for _, a in ipairs(archs) do
    local hidden = {}
    for i = 1, a[1] do hidden[i] = a[2] end
    local name = a[1] .. "x" .. a[2]
    local net = sn.mlp { inputs = 6, hidden = hidden, outputs = 3, activation = "tanh", seed = 1,
                         input_names = { "normal", "view" } }
    net:render(g, { weights = weights })  -- compile and upload
    local load = loadavg()
    local t0 = sn.clock()
    net:render(g, { weights = weights })
    local t1 = sn.clock()
    net:render(g, { frames = frames + 1, weights = weights })
    local t2 = sn.clock()
    local per_frame = ((t2 - t1) - (t1 - t0)) / frames
    ms[name] = ms[name] or {}
    ms[name][#ms[name] + 1] = per_frame * 1e3
    ns[name] = ns[name] or {}
    ns[name][#ns[name] + 1] = per_frame / covered * 1e9
    print(("%-6s %4dx%-4d covered %7d (%2.0f%%)  %9.3f ms/frame  %8.1f ns/fragment  load %s"):format(name, sz[1], sz[2],
      covered, 100 * covered / (sz[1] * sz[2]), per_frame * 1e3, per_frame / covered * 1e9, load))
  end
end

print("\nTable 4.6 — ms per frame: ours | thesis (GTX 1060)")
print(("%-7s %21s %21s %21s"):format("net", "640x480", "1280x720", "1920x1080"))
for _, a in ipairs(archs) do
  local name = a[1] .. "x" .. a[2]
  local row = ("%-7s"):format(name)
  for i = 1, 3 do row = row .. ("  %9.2f | %8.3f"):format(ms[name][i], thesis_ms[name][i]) end
  print(row)
end
print("\nTable 4.7 — ns per covered fragment (ours: mean of the three sizes) | thesis")
for _, a in ipairs(archs) do
  local name = a[1] .. "x" .. a[2]
  local mean = (ns[name][1] + ns[name][2] + ns[name][3]) / 3
  print(("%-7s %9.1f | %6.1f"):format(name, mean, thesis_ns[name]))
end

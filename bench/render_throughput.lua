-- Rendering throughput of networks over a G-buffer, by both backends side by side: the fragment
-- shader ("gl") and the cpu kernels over the covered pixels ("cpu", what "auto" picks on a
-- software renderer). ms per frame and ns per covered fragment for 4x4, 8x8, 12x12 and 16x16
-- networks (hidden layers x width; tanh, inputs normal + view, RGB out) at 640x480, 960x720,
-- 1280x720 and 1920x1080, printed beside the thesis' tables 4.6 and 4.7 (a GTX 1060).
--
--   shadenet bench/render_throughput.lua [repeats] [backends] [weights] [archs] [sizes]
--     repeats:  timings per cell, the median is printed (default 3)
--     backends: gl,cpu (default both)
--     weights:  auto (uniform buffer where it fits, the default) | storage (gl only)
--     archs:    hidden layers x width, comma separated (default 4x4,8x8,12x12,16x16)
--     sizes:    image sizes, comma separated (default 640x480,960x720,1280x720,1920x1080, the
--               thesis' columns; others show no thesis figure)
--
-- The G-buffer is a unit sphere seen from 2.7 units (41-55% of the frame covered). A timing is
-- (t(frames + 1) - t(1)) / frames with `frames` chosen so it lasts about half a second (sized
-- from a trial of about 0.1 s): what a frame costs after the G-buffer pass, without the final
-- image's way back to Lua. For gl that is the draw; for cpu the read-back of the attributes
-- inside the sphere's box, the network and the image. "load" is the 1-minute load average
-- before the cell: other work on a shared machine slows it.
local sn = require "shadenet"
package.path = (arg[0]:match("^(.*)/[^/]*$") or ".") .. "/?.lua;" .. package.path
local B = require "common"

local thesis_sizes = { "640x480", "960x720", "1280x720", "1920x1080" }  -- the columns of thesis_ms
local script = "bench/render_throughput.lua"
local specs = {
  { "repeats", "3", B.whole(1) },
  { "backends", "gl,cpu", B.list(B.one_of { "gl", "cpu" }) },
  { "weights", "auto", B.one_of { "auto", "storage" } },
  { "archs", "4x4,8x8,12x12,16x16", B.list(B.arch) },
  { "sizes", table.concat(thesis_sizes, ","), B.list(B.size) },
}
local o = B.args(script, specs)
local repeats, backends, weights, archs, sizes = o.repeats, o.backends, o.weights, o.archs, o.sizes
local has_gl = false
for _, b in ipairs(backends) do has_gl = has_gl or b == "gl" end
if weights ~= "auto" and not has_gl then
  B.fail(script, specs, "weights '" .. weights .. "' is for the gl backend, and backends '" ..
         table.concat(backends, ",") .. "' has no gl")
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

local thesis_ms = { ["4x4"] = { 0.879, nil, 1.697, 2.177 }, ["8x8"] = { 4.263, nil, 8.241, 10.067 },
                    ["12x12"] = { 12.754, nil, 24.002, 29.653 }, ["16x16"] = { 29.117, nil, 52.655, 66.710 } }
local thesis_ns = { ["4x4"] = 15.8, ["8x8"] = 79.3, ["12x12"] = 237.3, ["16x16"] = 538.9 }
local function thesis_at(name, sz)
  for i, s in ipairs(thesis_sizes) do
    if s == sz[1] .. "x" .. sz[2] then return thesis_ms[name] and thesis_ms[name][i] end
  end
end

-- Seconds per frame of one backend on one G-buffer.
local function per_frame(net, g, backend)
  local o = { backend = backend, weights = backend == "gl" and weights or nil }
  net:render(g, o)  -- compile and upload
  local t0 = sn.clock()
  net:render(g, o)
  local one = sn.clock() - t0
  -- Seconds of `frames` frames beyond a render of one.
  local function span(frames)
    o.frames = 1
    local t1 = sn.clock()
    net:render(g, o)
    local t2 = sn.clock()
    o.frames = frames + 1
    net:render(g, o)
    return math.max(0, (sn.clock() - t2) - (t2 - t1))
  end
  -- A trial of about 0.1 s sized from `one`, then the timing sized from the trial's frames:
  -- `one` includes the image's way back to Lua, which can outweigh a fast draw (a GPU's).
  local frames = math.max(2, math.ceil(0.1 / math.max(one, 1e-4)))
  local s = span(frames)
  if s < 0.4 then
    frames = math.max(2, math.ceil(frames * 0.5 / math.max(s, 1e-3)))
    s = span(frames)
  end
  return s / frames
end

local mesh = sphere(48, 96)
local info = sn.gl_info()
print(("device: %s (OpenGL %s); cpu threads: %s; %d repeats per cell (median); weights: %s"):format(info.renderer,
  info.version, os.getenv("SHADENET_THREADS") or "all", repeats, weights))

local ms, ns = {}, {}  -- [backend][arch][size index]
for _, b in ipairs(backends) do ms[b], ns[b] = {}, {} end
for si, sz in ipairs(sizes) do
  local scene = sn.scene { mesh = mesh, size = sz, views = { count = 1, elevation = 0, distance = 2.7 } }
  local g = scene:gbuffer { view = 1, attributes = { "normal", "view" } }
  local covered = g:covered()
  for _, a in ipairs(archs) do
    local hidden = {}
    for i = 1, a[1] do hidden[i] = a[2] end
    local name = a[1] .. "x" .. a[2]
    local net = sn.mlp { inputs = 6, hidden = hidden, outputs = 3, activation = "tanh", seed = 1,
                         input_names = { "normal", "view" } }
    local row = ("%-6s %4dx%-4d covered %7d (%2.0f%%)"):format(name, sz[1], sz[2], covered,
                                                           100 * covered / (sz[1] * sz[2]))
    for _, b in ipairs(backends) do
      local load = B.load()
      local t = {}
      for r = 1, repeats do t[r] = per_frame(net, g, b) end
      local s = B.median(t)
      ms[b][name] = ms[b][name] or {}
      ns[b][name] = ns[b][name] or {}
      ms[b][name][si], ns[b][name][si] = s * 1e3, s / covered * 1e9
      row = row .. ("  %s %9.3f ms %7.1f ns/frag (load %s)"):format(b, s * 1e3, s / covered * 1e9, load)
    end
    print(row)
  end
end

local function cell(v, fmt) return v and fmt:format(v) or "-" end
print("\nTable 4.6 -- ms per frame: ours (" .. table.concat(backends, " | ") .. ") | thesis (GTX 1060)")
local head = ("%-7s"):format("net")
for _, sz in ipairs(sizes) do head = head .. ("  %28s"):format(sz[1] .. "x" .. sz[2]) end
print(head)
for _, a in ipairs(archs) do
  local name = a[1] .. "x" .. a[2]
  local row = ("%-7s"):format(name)
  for si = 1, #sizes do
    local parts = {}
    for _, b in ipairs(backends) do parts[#parts + 1] = cell(ms[b][name][si], "%.2f") end
    parts[#parts + 1] = cell(thesis_at(name, sizes[si]), "%.3f")
    row = row .. ("  %28s"):format(table.concat(parts, " | "))
  end
  print(row)
end
print("\nTable 4.7 -- ns per covered fragment, mean over the sizes: ours (" .. table.concat(backends, " | ")
      .. ") | thesis")
for _, a in ipairs(archs) do
  local name = a[1] .. "x" .. a[2]
  local parts = {}
  for _, b in ipairs(backends) do
    local sum = 0
    for si = 1, #sizes do sum = sum + ns[b][name][si] end
    parts[#parts + 1] = ("%.1f"):format(sum / #sizes)
  end
  parts[#parts + 1] = cell(thesis_ns[name], "%.1f")
  print(("%-7s %s"):format(name, table.concat(parts, " | ")))
end

-- The loaders' resource limits (docs/reliability.md, "Limits"): each exceeded one is an error
-- naming the file, the quantity and the limit, with how to raise it; sn.limits{...} raises (or
-- lowers) them for the whole process and returns the old ones; the defaults still hold after.
local sn = require "shadenet"

local defaults = sn.limits()
assert(defaults.file_bytes == 2 ^ 30 and defaults.shader_bytes == 2 ^ 24 and defaults.image_pixels == 2 ^ 28
       and defaults.image_channels == 64 and defaults.node_placements == 2 ^ 16 and defaults.mesh_vertices == 2 ^ 26
       and defaults.mesh_indices == 2 ^ 28 and defaults.dataset_cache_bytes == 2 ^ 30, "the documented defaults")

-- The dataset cache keeps at most dataset_cache_bytes of rows: two datasets of ~28 KB each
-- under a 40 KB bound leave one cached, and the first is built again.
do
  local old = sn.limits { dataset_cache_bytes = 40000 }
  sn.dataset_cache_clear()
  local function sample(seed) return sn.dataset.sample { target = sn.lighting.phong {}, n = 800, seed = seed } end
  sample(1)
  sample(2)
  assert(sn.dataset_stats().cached == 1, "one dataset of 28.8 KB under the 40 KB bound")
  local builds = sn.dataset_stats().builds
  sample(1)
  assert(sn.dataset_stats().builds == builds + 1, "the dropped one is built again")
  sn.limits(old)
  sn.dataset_cache_clear()
end

local function fails(f, text, ...)
  local ok, err = pcall(f, ...)
  assert(not ok and tostring(err):find(text, 1, true), "expected '" .. text .. "', got: " .. tostring(err))
end

local dir = sn.fs.tempdir("test_limits")
local mesh = "meshes/test_blob.glb"
local mesh_bytes = #io.open(mesh, "rb"):read("*a")
local net = sn.mlp { inputs = 6, hidden = { 4 }, outputs = 3 }
net:save(dir .. "/net.snmlp")
local rows = {}
for i = 1, 50 do rows[i] = { i } end
local data = sn.dataset { x = rows, y = rows, split = 0.5 }
data:export(dir .. "/data.csv")
local image = sn.scene { mesh = mesh, size = { 48, 32 } }:render(sn.lighting.phong {})
image:save(dir .. "/img.exr")

-- file_bytes: every file read whole (meshes, datasets, checkpoints).
local old = sn.limits { file_bytes = 100 }
assert(old.file_bytes == 2 ^ 30 and sn.limits().file_bytes == 100, "sn.limits returns the limits before the call")
fails(sn.mesh.load, "cannot read mesh file '" .. mesh .. "': " .. mesh_bytes .. " bytes, above the limit of 100 bytes " ..
                    "(sn.limits{ file_bytes = ... } raises it)", mesh)
fails(sn.load, "above the limit of 100 bytes (sn.limits{ file_bytes = ... } raises it)", dir .. "/net.snmlp")
fails(sn.dataset.load, "above the limit of 100 bytes", dir .. "/data.csv")
sn.limits { file_bytes = 2 ^ 31 }  -- raised past the default
assert(sn.mesh.load(mesh) and sn.load(dir .. "/net.snmlp") and sn.dataset.load(dir .. "/data.csv"), "raised: they load")

-- shader_bytes: GLSL sources and their includes.
sn.limits { shader_bytes = 64 }
fails(sn.program, "above the limit of 64 bytes (sn.limits{ shader_bytes = ... } raises it)",
      { compute = "tests/data/shaders/poly.comp", defines = { LOCAL_SIZE = 64 } })
sn.limits { shader_bytes = 2 ^ 25 }
assert(sn.program { compute = "tests/data/shaders/poly.comp", defines = { LOCAL_SIZE = 64 } }, "raised: it compiles")

-- image_pixels, image_channels: from the header, before any pixel is read.
sn.limits { image_pixels = 1000 }
fails(sn.image.load, "48x32 is 1536 pixels, above the limit of 1000 (sn.limits{ image_pixels = ... } raises it)",
      dir .. "/img.exr")
sn.limits { image_pixels = 1536, image_channels = 3 }
fails(sn.image.load, "4 channels, above the limit of 3 (sn.limits{ image_channels = ... } raises it)", dir .. "/img.exr")
sn.limits { image_channels = 4 }
assert(select(1, sn.image.load(dir .. "/img.exr"):size()) == 48, "raised: it loads")

-- Bad settings are errors, and sn.limits(old) puts the defaults back.
fails(sn.limits, "sn.limits option 'mesh_vertices' must be at least 1, got 0", { mesh_vertices = 0 })
fails(sn.limits, "sn.limits option 'image_pixels': integer expected, got 1.5", { image_pixels = 1.5 })
fails(sn.limits, "sn.limits: unknown option 'pixels'", { pixels = 5 })
sn.limits(old)
for k, v in pairs(defaults) do assert(sn.limits()[k] == v, k .. " is back to its default") end
fails(sn.image.load, "above the limit of 268435456", "tests/data/huge_declared.png")
os.execute("rm -rf '" .. dir .. "'")
print("limits: ok")

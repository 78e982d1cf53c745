-- Writes the seed corpora of the fuzz targets (tests/fuzz/corpus/TARGET/): small valid files of
-- every kind each loader reads, made by shadenet itself, so fuzzing starts from inputs that reach
-- deep into the parsers. Run from the project root: build/shadenet tests/fuzz/make_seeds.lua
local sn = require "shadenet"
local root = "tests/fuzz/corpus/"

local function read(path)
  local f = assert(io.open(path, "rb"))
  local s = f:read("*a")
  f:close()
  return s
end
local function seed(target, name, bytes)
  sn.fs.mkdir(root .. target)
  sn.fs.write(root .. target .. "/" .. name, bytes)
end
local scratch = sn.fs.tempdir("make_seeds")
local SEP = "\n--8<--\n"   -- fuzz_input.h: parts of an input holding several files

-- gltf: a glTF with an embedded buffer, procedural meshes as GLB (normals, UVs, tangents, a
-- transform), and a hierarchy of nodes.
seed("gltf", "box.gltf", read("../shared/meshes/Box.gltf"))
local meshes = {
  sphere = sn.mesh.sphere { segments = 6, rings = 4 },
  torus = sn.mesh.torus { segments = 6, sides = 4 },
  plane = sn.mesh.plane { subdivisions = 2 }:transformed { rotate = { 30, 1, 0, 0 }, scale = 2 },
}
for name, m in pairs(meshes) do
  m:save(scratch .. "/" .. name .. ".glb")
  seed("gltf", name .. ".glb", read(scratch .. "/" .. name .. ".glb"))
end
seed("gltf", "nodes.gltf", [[{"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],
"nodes":[{"children":[1],"translation":[1,0,0]},{"children":[2],"rotation":[0,0.7071,0,0.7071]},
{"mesh":0,"scale":[2,2,2]}],
"meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],
"buffers":[{"byteLength":42,"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIA"}],
"bufferViews":[{"buffer":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":6}],
"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]},
{"bufferView":1,"componentType":5123,"count":3,"type":"SCALAR"}]}]])

-- image: the first byte picks the extension (fuzz_image.cpp's list), the rest is the file.
local extensions = { "png", "exr", "hdr", "tga", "bmp", "jpg", "dds", "tif", "ppm", "psd" }
local img = sn.image.new { width = 5, height = 3, channels = 4 }
for y = 1, 3 do
  for x = 1, 5 do img:set(x, y, { x / 5, y / 3, 0.5, 1 }) end
end
for k, ext in ipairs(extensions) do
  local ok = pcall(function() img:save(scratch .. "/img." .. ext) end)
  if ok then seed("image", "img." .. ext, string.char(k - 1) .. read(scratch .. "/img." .. ext)) end
end
-- Formats image:save does not write, by hand: binary PPM, Radiance HDR, uncompressed TGA.
seed("image", "img.ppm", string.char(8) .. "P6\n2 1\n255\n" .. string.char(255, 0, 0, 0, 128, 255))
seed("image", "img.hdr", string.char(2) .. "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 2\n" ..
                         string.char(128, 64, 32, 129, 10, 20, 30, 128))
seed("image", "img.tga", string.char(3) .. string.char(0, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 0, 1, 0, 24, 0) ..
                         string.char(255, 0, 0, 0, 255, 0))
seed("image", "volume.dds", string.char(6) .. read("tests/data/volume.dds"))

-- checkpoint: networks with each kind of section (activation parameter, conditions, a user's
-- activation by definition, a best snapshot).
local nets = {
  tanh = sn.mlp { inputs = 6, hidden = { 3, 2 }, outputs = 3 },
  sine = sn.mlp { inputs = 6, hidden = { 4 }, outputs = 3, activation = "sine", omega = 30 },
  leaky = sn.mlp { inputs = 6, hidden = { 2 }, outputs = 1, activation = "leaky_relu", slope = 0.1,
                   output_activation = "sigmoid" },
}
for name, net in pairs(nets) do
  net:save(scratch .. "/" .. name .. ".snmlp")
  seed("checkpoint", name .. ".snmlp", read(scratch .. "/" .. name .. ".snmlp"))
end
seed("checkpoint", "softsign.snmlp", read("tests/data/checkpoint_softsign.snmlp"))
seed("checkpoint", "v1.snmlp", read("tests/data/checkpoint_v1.snmlp"))

-- dataset: NumPy (sidecar, inputs, targets as three parts) and CSV.
local x, y = {}, {}
for i = 1, 5 do
  local a = i / 5
  x[i] = { a, 1 - a, a * a, 0, 0, 1 }
  y[i] = { a, a * 0.5, 1 - a }
end
local ds = sn.dataset { x = x, y = y, split = 0.6, input_names = { "normal", "view" } }
ds:export(scratch .. "/ds")
seed("dataset", "numpy", read(scratch .. "/ds.json") .. SEP .. read(scratch .. "/ds.inputs.npy") .. SEP ..
                         read(scratch .. "/ds.targets.npy"))
ds:export(scratch .. "/ds.csv")
seed("dataset", "rows.csv", read(scratch .. "/ds.csv"))

-- run_file: records as a sweep writes them (fuzz_run_file.cpp's run has config {layers = 4,
-- width = 6}): one that counts, one of another configuration, one the reader must refuse.
seed("run_file", "finished.json",
     '{"id":"run","config":{"layers":4,"width":6},"result":{"val_mse":0.0012,"image_mse":0.003,"epochs":20,' ..
     '"curve":[0.1,0.01,0.0012],"diverged":false,"time":1.5}}')
seed("run_file", "other_config.json", '{"id":"run","config":{"layers":2,"width":6},"result":{"val_mse":0.5}}')
seed("run_file", "negative.json", '{"id":"run","config":{"layers":4,"width":6},"result":{"val_mse":-1e-3}}')
seed("run_file", "escapes.json", '{"config":{"layers":4,"width":6},"note":"a\\u00e9\\n\\"b\\"","x":[1e308,-0.0,null,true]}')

-- include: a shader, a driver log, then files "a.glsl", "b.glsl" it includes from memory, and
-- one of shadenet's own shaders that includes files on disk.
seed("include", "memory.comp", table.concat({
  "#version 450\n#include \"a.glsl\"\nlayout(local_size_x = LOCAL_SIZE) in;\nvoid main() { f(); }\n",
  "0:3(5): error: `g' undeclared\n0:1(1): warning: unused\n",
  "#include \"b.glsl\"\nvoid f() { g(); }\n",
  "#define TWO 2\nfloat g() { return TWO; }\n",
}, SEP))
seed("include", "mlp_eval.comp", read("shaders/mlp_eval.comp") .. SEP .. "0(12) : error C1008: undefined variable\n")
seed("include", "cycle.comp", table.concat({ "#include \"a.glsl\"\n", "", "#include \"b.glsl\"\n", "#include \"a.glsl\"\n" }, SEP))

-- activation: a definition's GLSL of f, then of f' (the built-ins' own, which use every form the
-- translator reads: expressions, statements, bvec mixes, shadenet's GLSL functions).
seed("activation", "softsign.glsl", "x / (1.0 + abs(x))" .. SEP .. "vec4 d = 1.0 + abs(x); return 1.0 / (d * d);")
seed("activation", "squareplus.glsl", "vec4 s = sqrt(z * z + 4.0); return mix(2.0 / (s - z), 0.5 * (z + s), greaterThanEqual(z, vec4(0.0)));"
     .. SEP .. "return 0.5 + 0.5 * z / sqrt(z * z + 4.0);")
seed("activation", "gelu.glsl", "return 0.5 * z * (1.0 + sn_gelu_tanh(z));" .. SEP ..
     "vec4 t = sn_gelu_tanh(z);\nreturn 0.5 * (1.0 + t) + 0.5 * z * (1.0 - t * t) * 0.7978845608028654 * (1.0 + 0.134145 * z * z);")
seed("activation", "functions.glsl", table.concat({
  "const float k = 2.0; /* c */ vec4 y = x; y *= k; y += smoothstep(-1.0, 1.0, x) - fract(x) + mod(x, 3.0);\n" ..
  "bool far = p > 1.0 && !(p < -1.0) || p == 0.5; return far ? pow(abs(y), vec4(1.5)) + atan(y) : log2(exp2(y)) + inversesqrt(1.0 + y * y);",
  "return step(0.0, x) * sign(x) + clamp(x, -1.0, 1.0) + tanh(x) * cosh(x) - sinh(x) + asinh(x) + acos(0.5) + asin(0.5) + radians(degrees(x));",
}, SEP))

os.execute("rm -rf '" .. scratch .. "'")
print("seeds written under " .. root)

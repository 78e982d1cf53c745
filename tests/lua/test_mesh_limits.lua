-- glTF files that used to take the process down or load wrong (issue 13): a chain of nodes
-- 30,000 deep overflowed the stack; one node listed 200,000 times grew the mesh to 23 GB;
-- a negative bufferView loaded as zeros. All are now errors naming
-- the file and what is wrong, and a tree at the limits still loads.
local sn = require "shadenet"

sn.fs.mkdir("out/mesh_limits")
-- One triangle (base64 of 9 floats: 0,0,0  1,0,0  0,1,0).
local buffer = '{"byteLength":36,"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}'
local function gltf(nodes)
  return '{"asset":{"version":"2.0"},"buffers":[' .. buffer .. '],"bufferViews":[{"buffer":0,"byteLength":36}],'
    .. '"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],'
    .. '"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"scenes":[{"nodes":[0]}],"scene":0,"nodes":['
    .. table.concat(nodes, ",") .. ']}'
end
local function chain(depth)
  local nodes = {}
  for i = 1, depth - 1 do nodes[i] = '{"children":[' .. i .. ']}' end
  nodes[depth] = '{"mesh":0}'
  return gltf(nodes)
end
local function repeated(times)
  local kids = {}
  for i = 1, times do kids[i] = "1" end
  return gltf { '{"children":[' .. table.concat(kids, ",") .. ']}', '{"mesh":0}' }
end

local cases = {
  { "deep.gltf", chain(30000), "nests nodes more than 256 deep (the limit, scene/mesh.h)" },
  { "repeated.gltf", repeated(200000), "places nodes more than 65536 times (the limit, scene/mesh.h; a node listed many times?)" },
}
for _, c in ipairs(cases) do
  local path = "out/mesh_limits/" .. c[1]
  sn.fs.write(path, c[2])
  local ok, err = pcall(sn.mesh.load, path)
  assert(not ok and tostring(err):find(c[3], 1, true), c[1] .. ": " .. tostring(err))
end

-- Values outside the glTF specification are errors, not defaults: a POSITION bufferView of -5
-- loaded as zeros.
local function with_accessor(accessor)
  return '{"asset":{"version":"2.0"},"buffers":[' .. buffer .. '],"bufferViews":[{"buffer":0,"byteLength":36}],'
    .. '"accessors":[' .. accessor .. '],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],'
    .. '"scenes":[{"nodes":[0]}],"scene":0,"nodes":[{"mesh":0}]}'
end
local bad = {
  { "view_minus5.gltf", '{"bufferView":-5,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}',
    "has bufferView -5; it must be a view's index or absent" },
}
for _, c in ipairs(bad) do
  local path = "out/mesh_limits/" .. c[1]
  sn.fs.write(path, with_accessor(c[2]))
  local ok, err = pcall(sn.mesh.load, path)
  assert(not ok and tostring(err):find(c[3], 1, true), c[1] .. ": " .. tostring(err))
end

-- At the limits: 256 levels, and 1,000 placements of one triangle, load.
sn.fs.write("out/mesh_limits/deep_ok.gltf", chain(256))
assert(select(2, sn.mesh.load("out/mesh_limits/deep_ok.gltf"):counts()) == 3, "256 levels load")
sn.fs.write("out/mesh_limits/repeated_ok.gltf", repeated(1000))
assert(select(2, sn.mesh.load("out/mesh_limits/repeated_ok.gltf"):counts()) == 3000, "1,000 placements load")
print("ok")

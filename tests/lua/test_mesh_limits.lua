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
  { "deep.gltf", chain(30000), "nests nodes more than 256 deep (the limit, scene/gltf.h)" },
  { "repeated.gltf", repeated(200000),
    "places nodes more than 65536 times (a node listed many times?) (sn.limits{ node_placements = ... } raises it)" },
}
for _, c in ipairs(cases) do
  local path = "out/mesh_limits/" .. c[1]
  sn.fs.write(path, c[2])
  local ok, err = pcall(sn.mesh.load, path)
  assert(not ok and tostring(err):find(c[3], 1, true), c[1] .. ": " .. tostring(err))
end

-- Values outside the glTF specification are errors, not defaults: a POSITION bufferView of -5
-- loaded as zeros; tinygltf reads a byteOffset of -1 (or 1.5, or "8") as absent, i.e. 0, which
-- read normals as positions; the loader reads the JSON's integers itself.
local function with_accessor(accessor, view, primitive, node)
  return '{"asset":{"version":"2.0"},"buffers":[' .. buffer .. '],"bufferViews":[' .. (view or '{"buffer":0,"byteLength":36}') .. '],'
    .. '"accessors":[' .. accessor .. '],"meshes":[{"primitives":[' .. (primitive or '{"attributes":{"POSITION":0}}') .. ']}],'
    .. '"scenes":[{"nodes":[0]}],"scene":0,"nodes":[' .. (node or '{"mesh":0}') .. ']}'
end
local good = '{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}'
local function accessor(extra) return '{' .. extra .. ',"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}' end
local bad = {
  { "view_minus5.gltf", { accessor '"bufferView":-5' }, "accessors[0].bufferView is -5; glTF requires a non-negative integer there" },
  { "view_minus1.gltf", { accessor '"bufferView":-1' }, "accessors[0].bufferView is -1; glTF requires a non-negative integer there" },
  { "offset_minus1.gltf", { accessor '"bufferView":0,"byteOffset":-1' }, "accessors[0].byteOffset is -1; glTF requires" },
  { "offset_half.gltf", { accessor '"bufferView":0,"byteOffset":1.5' }, "accessors[0].byteOffset is 1.5; glTF requires" },
  { "offset_text.gltf", { accessor '"bufferView":0,"byteOffset":"8"' }, 'accessors[0].byteOffset is a string ("8"); glTF requires' },
  { "view_offset_minus1.gltf", { good, '{"buffer":0,"byteLength":36,"byteOffset":-1}' },
    "bufferViews[0].byteOffset is -1; glTF requires a non-negative integer there" },
  { "stride_minus4.gltf", { good, '{"buffer":0,"byteLength":36,"byteStride":-4}' }, "bufferViews[0].byteStride is -4" },
  { "indices_half.gltf", { good, nil, '{"attributes":{"POSITION":0},"indices":0.5}' }, "meshes[0].primitives[0].indices is 0.5" },
  { "child_minus1.gltf", { good, nil, nil, '{"mesh":0,"children":[-1]}' }, "nodes[0].children[0] is -1" },
  { "mesh_null.gltf", { good, nil, nil, '{"mesh":null}' }, "nodes[0].mesh is null" },
}
for _, c in ipairs(bad) do
  local path = "out/mesh_limits/" .. c[1]
  sn.fs.write(path, with_accessor(c[2][1], c[2][2], c[2][3], c[2][4]))
  local ok, err = pcall(sn.mesh.load, path)
  assert(not ok and tostring(err):find("mesh file '" .. path .. "': " .. c[3], 1, true), c[1] .. ": " .. tostring(err))
end
-- A .glb is checked alike (its JSON chunk).
local function u32(n) return string.char(n % 256, math.floor(n / 256) % 256, math.floor(n / 65536) % 256, math.floor(n / 16777216)) end
local function glb(json)
  json = json:gsub('"uri":"[^"]*"', ""):gsub(",}", "}")
  while #json % 4 ~= 0 do json = json .. " " end
  local bin = u32(0) .. u32(0) .. u32(0) .. u32(0x3f800000) .. u32(0) .. u32(0) .. u32(0) .. u32(0x3f800000) .. u32(0)
  return "glTF" .. u32(2) .. u32(12 + 8 + #json + 8 + #bin) .. u32(#json) .. "JSON" .. json .. u32(#bin) .. "BIN\0" .. bin
end
sn.fs.write("out/mesh_limits/ok.glb", glb(with_accessor(good)))
assert(select(2, sn.mesh.load("out/mesh_limits/ok.glb"):counts()) == 3, "the .glb loads")
sn.fs.write("out/mesh_limits/offset_minus1.glb", glb(with_accessor(accessor '"bufferView":0,"byteOffset":-1')))
local ok, err = pcall(sn.mesh.load, "out/mesh_limits/offset_minus1.glb")
assert(not ok and err:find("accessors[0].byteOffset is -1; glTF requires a non-negative integer there", 1, true), tostring(err))

-- At the limits: 256 levels, and 1,000 placements of one triangle, load.
sn.fs.write("out/mesh_limits/deep_ok.gltf", chain(256))
assert(select(2, sn.mesh.load("out/mesh_limits/deep_ok.gltf"):counts()) == 3, "256 levels load")
sn.fs.write("out/mesh_limits/repeated_ok.gltf", repeated(1000))
assert(select(2, sn.mesh.load("out/mesh_limits/repeated_ok.gltf"):counts()) == 3000, "1,000 placements load")
-- Raised where a scene needs more: the 200,000 placements load; the merged vertices have their
-- own limit.
local old = sn.limits { node_placements = 250000 }
assert(select(2, sn.mesh.load("out/mesh_limits/repeated.gltf"):counts()) == 600000, "200,000 placements load when raised")
sn.limits { mesh_vertices = 2999 }
local ok, err = pcall(sn.mesh.load, "out/mesh_limits/repeated_ok.gltf")
assert(not ok and err:find("has more than 2999 vertices (at mesh 0 primitive 0, after its nodes' placements) " ..
                           "(sn.limits{ mesh_vertices = ... } raises it)", 1, true), tostring(err))
sn.limits { mesh_vertices = 3000, mesh_indices = 2999 }
ok, err = pcall(sn.mesh.load, "out/mesh_limits/repeated_ok.gltf")
assert(not ok and err:find("has more than 2999 indices", 1, true), tostring(err))
sn.limits(old)
assert(not pcall(sn.mesh.load, "out/mesh_limits/repeated.gltf"), "the default limit again")
print("ok")

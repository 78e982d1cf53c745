-- expect: mesh_truncated\.lua:14: mesh file '.*duck_half\.gltf': is not a valid glTF file \(tinygltf: .*parse error
-- A copy of Duck.gltf cut in half (the JSON and its base64 buffer both end mid-way).
local sn = require "shadenet"

local src = assert(io.open((os.getenv("SHADENET_SHARED") or "../shared") .. "/meshes/Duck.gltf", "rb"))
local bytes = src:read("*a")
src:close()
local path = sn.fs.tempdir("error") .. "/duck_half.gltf"
local out = assert(io.open(path, "wb"))
out:write(bytes:sub(1, math.floor(#bytes / 2)))
out:close()
local ok, err = pcall(function()
  -- (not a tail call, so the error names this line)
  local mesh = sn.mesh.load(path)
  return mesh
end)
assert(not ok, "a truncated file loaded")
error(err, 0)

-- The meshes the experiments use, and what the scene says about meshes it has to fix.
local sn = require "shadenet"

-- meshes/: the cloth (training) and the blob (testing), as make_meshes.lua wrote them.
local cloth = sn.mesh.load("meshes/cloth.glb")
local verts, idx = cloth:counts()
assert(idx / 3 >= 10000 and idx / 3 <= 60000, "cloth triangles: " .. idx / 3)
assert(cloth:has("normal") and cloth:has("uv") and cloth:has("texture"), tostring(cloth))
assert(not cloth:normals_computed(), "the cloth's normals are analytic")
local lo, hi = cloth:bounds()
assert(hi[2] - lo[2] > 1.5 and hi[3] - lo[3] > 0.3, "a draped sheet, not a plane")
local blob = sn.mesh.load("meshes/test_blob.glb")
assert(blob:has("normal") and blob:has("uv") and not blob:has("texture"), tostring(blob))
for _, f in ipairs { "meshes/cloth.glb", "meshes/test_blob.glb" } do
  local h = assert(io.open(f, "rb"))
  local size = h:seek("end")
  h:close()
  assert(size < 2 * 1024 * 1024, f .. " is " .. size .. " bytes")
end

-- The folds are real: normals across the cloth vary a lot (a flat sheet would not).
local scene = sn.scene { mesh = cloth, size = { 64, 64 }, views = { count = 1, elevation = 0 } }
local g = scene:gbuffer { attributes = { "normal" } }
local n = g:read("normal")
local min_x, max_x = 1, -1
for y = 1, 64 do
  for x = 1, 64 do
    local p = n:get(x, y)
    if p[4] > 0.5 then min_x, max_x = math.min(min_x, p[1]), math.max(max_x, p[1]) end
  end
end
assert(max_x - min_x > 1.0, string.format("normal x spans %.2f..%.2f", min_x, max_x))

-- A file without normals: the scene computes them and says so.
local text = assert(io.open("../shared/meshes/Box.gltf")):read("*a")
local stripped, count = text:gsub('"NORMAL"%s*:%s*%d+%s*,', "")
assert(count == 1, "Box.gltf has one NORMAL attribute")
local path = sn.fs.tempdir("test_dataset_meshes") .. "/box.gltf"
local f = assert(io.open(path, "w"))
f:write(stripped)
f:close()
local box = sn.scene { mesh = path, size = { 32, 32 } }
local notes = box:notes()
assert(#notes == 1 and notes[1]:match("has no normals") and notes[1]:match("computed"), "note: " .. tostring(notes[1]))
assert(box:meshes()[1]:normals_computed(), "computed normals are flagged on the mesh")
local d = box:dataset { target = sn.lighting.phong {}, samples = 100 }
assert(d:counts() == 80, "a dataset from the computed normals")

-- sn.procedural_mesh computes normals when none are given.
local tri = sn.procedural_mesh { positions = { 0, 0, 0, 1, 0, 0, 0, 1, 0 }, indices = { 1, 2, 3 } }
assert(tri:normals_computed(), "computed")
print("ok")

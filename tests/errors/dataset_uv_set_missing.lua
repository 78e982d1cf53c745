-- expect: dataset_uv_set_missing\.lua:7: attribute 'uv': mesh 'tests/data/tex_set1_missing\.gltf' has no texture coordinates \(TEXCOORD_1\)
local sn = require "shadenet"

-- The quad's material reads its texture from TEXCOORD_1 (texCoord 1); the file has only
-- TEXCOORD_0, so the mesh has no texture coordinates, and the error names the set it lacks.
local scene = sn.scene { mesh = "tests/data/tex_set1_missing.gltf", size = { 32, 32 } }
local data = scene:dataset { inputs = { "position", "uv" }, target = sn.lighting.phong {} }

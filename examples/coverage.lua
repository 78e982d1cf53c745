-- What two training sets cover: the thesis' hanging cloth seen from one ring of 8 views, and
-- the experiments' default, the cloth in 5 poses seen from 3 rings. Each is drawn against the
-- test blob (red: bins where the blob has pixels and the training rows have none).
--   build/shadenet examples/coverage.lua [OUT_DIR]      (default results/coverage)
local sn = require "shadenet"

local out = arg and arg[1] or "results/coverage"
local blob = sn.scene { mesh = "meshes/test_blob.glb", size = { 480, 360 } }
local poses = { {}, { rotate = { 60, 1, 0, 0 } }, { rotate = { -60, 1, 0, 0 } },
                { rotate = { 60, 0, 0, 1 } }, { rotate = { -60, 0, 0, 1 } } }
local sets = {
  { file = "coverage_cloth.png", label = "the hanging cloth, 8 views at 20 degrees (--data cloth)",
    scene = sn.scene { mesh = "meshes/cloth.glb", size = { 640, 480 }, views = { count = 8, elevation = 20 } } },
  { file = "coverage_poses.png", label = "the cloth in 5 poses, 3 rings of 8 views (--data poses, the default)",
    scene = sn.scene { mesh = "meshes/cloth.glb", size = { 640, 480 }, poses = poses,
                       views = { { count = 8, elevation = -30 }, { count = 8, elevation = 20 }, { count = 8, elevation = 60 } } } },
}
for _, s in ipairs(sets) do
  local data = s.scene:dataset { target = sn.lighting.phong {} }
  local c = data:coverage { against = blob, figure = out .. "/" .. s.file, title = s.label .. ", against the test blob" }
  print(string.format("%s: normals %.1f%%, views %.1f%% of bins; test blob outside: %.1f%% -> %s/%s", s.label,
                      100 * c.normal.fraction, 100 * c.view.fraction, 100 * c.outside.either, out, s.file))
end

-- expect: scene_empty_view_ring\.lua:4: sn\.scene option 'views' element 2 \(a view ring\) option 'count': a view ring needs 1\.\.4096 cameras, got 0
local sn = require "shadenet"
-- The second ring has no camera: a typo for 8, say; it must not silently vanish.
local scene = sn.scene { mesh = "meshes/test_blob.glb", views = { { count = 8, elevation = 20 }, { count = 0, elevation = 70 } } }

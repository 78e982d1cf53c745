-- expect: scene_render_view_range\.lua:5: scene:render option 'view': 3 is outside the scene's views 1\.\.2
-- scene:render's G-buffer errors name the script's line and the method it called.
local sn = require "shadenet"
local s = sn.scene { mesh = sn.mesh.sphere {}, size = { 8, 8 }, views = { count = 2 } }
local img = s:render(sn.lighting.phong {}, { view = 3 })

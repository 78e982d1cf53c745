-- expect: scene_render_light_key\.lua:5: scene:render option 'light': unknown key 'direction' \(valid: color, dir\)
local sn = require "shadenet"
local scene = sn.scene { mesh = sn.mesh.sphere {}, size = { 32, 32 }, views = { count = 1 } }
-- The same picture as without the light was drawn: the misspelt key went unread.
scene:render(sn.lighting.phong {}, { light = { direction = { -1, 0, 0 } } })

-- expect: scene_render_light_zero\.lua:5: scene:render light: light 'dir' must be a non-zero, finite direction
local sn = require "shadenet"
local scene = sn.scene { mesh = sn.mesh.sphere {}, size = { 32, 32 }, views = { count = 1 } }
-- The error named shadenet.scene.lua, inside the library, not this line.
scene:render(sn.lighting.phong {}, { light = { dir = { 0, 0, 0 } } })

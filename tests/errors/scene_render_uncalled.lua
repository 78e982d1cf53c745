-- expect: scene_render_uncalled\.lua:6: scene:render: a lighting model \(sn\.lighting\.\*\) or a network \(sn\.mlp\) expected, got the function sn\.lighting\.phong \(call it: sn\.lighting\.phong {\.\.\.}, or sn\.lighting\.phong {} for its defaults\)
-- A model's constructor left uncalled in scene:render gets the hint every other entry point gives.
local sn = require "shadenet"

local scene = sn.scene { mesh = sn.mesh.sphere {}, size = { 16, 16 }, views = { count = 1 } }
scene:render(sn.lighting.phong)

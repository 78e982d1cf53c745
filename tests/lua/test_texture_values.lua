-- A texture's values reach the G-buffer as the script and the CPU twin hold them: one made in a
-- script (2.5, -0.5, 0.123456) was clamped to [0, 1] and rounded to 8 bits on the GPU (1, 0,
-- 0.1216) while mesh:texture() still gave the originals. 8-bit values (k / 255) stay exact too.
local sn = require "shadenet"

local function drawn(texel)
  local t = sn.image.new { width = 2, height = 2, channels = 3 }
  for y = 1, 2 do for x = 1, 2 do t:set(x, y, texel) end end
  local quad = sn.procedural_mesh { name = "quad", positions = { -1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0 },
                                    uvs = { 0, 1, 1, 1, 1, 0, 0, 0 }, indices = { 1, 2, 3, 1, 3, 4 }, texture = t }
  local scene = sn.scene { mesh = quad, size = { 8, 8 }, views = { sn.camera { eye = { 0, 0, 3 } } } }
  return scene:gbuffer { attributes = { "base_color" } }:read("base_color"):get(4, 4)
end

for _, texel in ipairs { { 2.5, -0.5, 0.123456 }, { 0.2, 1 / 3, 0.7 }, { 1 / 255, 128 / 255, 1 } } do
  local got = drawn(texel)
  for c = 1, 3 do
    local want = sn.image.new { width = 1, height = 1, channels = 1, fill = texel[c] }:get(1, 1)[1]  -- as a float
    assert(got[c] == want, ("texel {%s} channel %d: drawn %.9g, the texture holds %.9g"):format(
      table.concat(texel, ", "), c, got[c], want))
  end
end
print("ok")

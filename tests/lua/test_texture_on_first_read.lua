-- A mesh's texture is decoded when first read (runtime/scene/texture.h): loading the textured
-- cloth, building a dataset of normals and views and rendering Phong and a network on it never
-- sample the texture, so they do not load OpenImageIO (about 0.15 s); reading the texture does.
local sn = require "shadenet"

local mapped = require "mapped"

local cloth = sn.scene { mesh = "meshes/cloth.glb", size = { 48, 36 }, views = { count = 2 } }
assert(cloth:meshes()[1]:has("texture"), "the cloth has a base-colour texture")
local data = cloth:dataset { inputs = { "normal", "view" }, target = sn.lighting.phong {}, samples = 500, seed = 1 }
assert(select(2, data:counts()) + data:counts() == 500)
local truth = cloth:render(sn.lighting.phong {}, { view = 1 })
local net = sn.mlp { inputs = { "normal", "view" }, hidden = { 4 }, outputs = 3, seed = 1 }
local shown = cloth:render(net, { view = 2 })
assert(sn.image.mse(truth, truth) == 0 and shown:size() == 48)
assert(not mapped("libshadenet_image"), "loading and rendering the cloth without its texture loaded the image module")

local texture = cloth:meshes()[1]:texture()
assert(mapped("libshadenet_image"), "reading the texture decodes it with the image module")
local w, h, c = texture:size()
assert(w == 256 and h == 256 and c >= 3, ("texture %dx%dx%d"):format(w, h, c))
-- The textured model samples it too, and its G-buffer attribute holds the texture's colours.
-- The G-buffer's base colour is the texture's (not the white a mesh without one is given).
local g = cloth:gbuffer { view = 1, attributes = { "base_color" } }:read("base_color")
local sum, covered = 0, 0
for y = 1, 36 do
  for x = 1, 48 do
    local p = g:get(x, y)
    if p[4] > 0.5 then sum, covered = sum + (p[1] + p[2] + p[3]) / 3, covered + 1 end
  end
end
local tsum = 0
for y = 1, 256 do
  for x = 1, 256 do
    local p = texture:get(x, y)
    tsum = tsum + (p[1] + p[2] + p[3]) / 3
  end
end
print(("covered %d, mean base colour %.3f, the texture's %.3f"):format(covered, sum / covered, tsum / 65536))
assert(covered > 100 and math.abs(sum / covered - tsum / 65536) < 0.1)
print("ok")

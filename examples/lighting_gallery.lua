-- Renders the cloth (and the Duck, with its texture) with every lighting model -- the built-ins
-- and the two defined in Lua + GLSL -- and writes one labelled image per model, plus an overview grid:
--   build/shadenet examples/lighting_gallery.lua [out_dir]      (default out/gallery)
-- The light comes from the upper right, in front (dir = {0.5, 0.7, 0.6}): highlights sit where
-- the surface's normal bisects the light and the view, on the upper-right faces of folds.
local sn = require "shadenet"
-- The models defined in Lua + GLSL (examples/lighting/) sit beside the built-ins.
package.path = "examples/lighting/?.lua;" .. package.path
local oren_nayar, aniso_ggx = require "oren_nayar", require "aniso_ggx"

local out = arg[1] or "out/gallery"
sn.fs.mkdir(out)
local light = { dir = { 0.5, 0.7, 0.6 }, color = { 1, 1, 1 } }

-- The camera looks at the front of the cloth from a little above (elevation 15 degrees).
local cloth = sn.scene { mesh = "meshes/cloth.glb", size = { 384, 384 },
                         views = { count = 1, elevation = 15 }, light = light }
local duck = sn.scene { mesh = "../shared/meshes/Duck.gltf", size = { 384, 384 },
                        views = { count = 8, elevation = 20 }, light = light }

local shots = {
  { cloth, sn.lighting.phong {}, "Phong" },
  { cloth, sn.lighting.blinn_phong {}, "Blinn-Phong" },
  { cloth, sn.lighting.ggx {}, "GGX gold, roughness 0.3" },
  { cloth, sn.lighting.ggx { roughness = 0.6, f0 = { 0.95, 0.64, 0.54 } }, "GGX copper, roughness 0.6" },
  { cloth, sn.lighting.ggx { roughness = 0.4, f0 = 0.04, diffuse = { 0.6, 0.1, 0.1 } }, "GGX red plastic" },
  { cloth, sn.lighting.toon3 {}, "toon3 (thesis 4.4)" },
  { cloth, sn.lighting.textured_phong {}, "textured Phong (fabric)" },
  { duck, sn.lighting.textured_phong {}, "textured Phong (Duck)", 2 },
  { duck, sn.lighting.ggx { roughness = 0.2 }, "GGX gold (Duck)", 2 },
  { cloth, oren_nayar:with { sigma = 0.8 }, "Oren-Nayar, sigma 0.8 (Lua)" },
  { cloth, aniso_ggx, "anisotropic GGX 0.3 x 0.7 (Lua)" },
  { duck, aniso_ggx, "anisotropic GGX (Duck, Lua)", 2 },
}

local panels = {}
for i, shot in ipairs(shots) do
  local scene, model, label, view = shot[1], shot[2], shot[3], shot[4] or 1
  local img = scene:render(model, { view = view })
  local labelled = sn.image.grid { panels = { { image = img, caption = label } }, background = { 0.25, 0.25, 0.25 },
                                   text = { 1, 1, 1 } }
  local file = string.format("%s/%02d_%s.png", out, i, label:gsub("[^%w]+", "_"):gsub("_$", ""):lower())
  labelled:save(file)
  panels[#panels + 1] = { image = img, caption = label }
  print(file, tostring(model))
end
sn.image.grid { panels = panels, columns = 3, background = { 0.25, 0.25, 0.25 }, text = { 1, 1, 1 },
                title = "shadenet ground truth: one light, every model" }:save(out .. "/gallery.png")
print(out .. "/gallery.png")

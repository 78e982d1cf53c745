-- Figures 4.4 and 4.5: what GGX networks of different depth (width 6: 4..14 hidden layers) and
-- width (6 hidden layers: 4..14 neurons) render, beside the ground truth, with |error| heatmaps
-- on one colour scale per mesh, on the training mesh and on a different test mesh from two views.
--   shadenet scripts/fig_4_4_4_5_grids.lua [--quick] [--shard i/n] [--out DIR] [--backend cpu|gl|auto]
package.path = (arg and arg[0] and arg[0]:match("^(.*)/[^/]*$") or ".") .. "/?.lua;" .. package.path
local exp = require "lib.experiment"
local grids = require "lib.grids"

local E = exp.start("fig_4_4_4_5_grids", arg)
local depth, width = {}, {}
for _, n in ipairs { 4, 6, 8, 10, 12, 14 } do
  depth[#depth + 1] = { layers = n, width = 6, label = n .. " layers" }
  width[#width + 1] = { layers = 6, width = n, label = "width " .. n }
end
grids.run(E, {
  model = "ggx",
  figures = {
    { file = "figures/fig_4_4_depth.png", title = "Figure 4.4 — GGX, width 6: 4 to 14 hidden layers", nets = depth },
    { file = "figures/fig_4_5_width.png", title = "Figure 4.5 — GGX, 6 hidden layers: width 4 to 14", nets = width },
  },
  table_title = "Figures 4.4 and 4.5 — validation MSE and image MSE on the training and the test mesh",
})

-- Figures 4.1 and 4.2: what Phong networks render with more layers (width 6: 8, 12 and 16 hidden
-- layers; the thesis saw blurrier, lower-contrast images as depth grows) and with wider layers (6
-- hidden layers: width 8, 10 and 16; the thesis saw colour shifts as width grows), beside the
-- ground truth, with |error| heatmaps on one colour scale per mesh, on the training mesh and on a
-- different test mesh from two views.
--   shadenet scripts/fig_4_1_4_2_phong.lua [--quick] [--shard i/n] [--out DIR] [--backend cpu|gl|auto]
package.path = (arg and arg[0] and arg[0]:match("^(.*)/[^/]*$") or ".") .. "/?.lua;" .. package.path
local exp = require "lib.experiment"
local grids = require "lib.grids"

local E = exp.start("fig_4_1_4_2_phong", arg)
local depth, width = {}, {}
for _, n in ipairs { 8, 12, 16 } do depth[#depth + 1] = { layers = n, width = 6, label = n .. " layers" } end
for _, n in ipairs { 8, 10, 16 } do width[#width + 1] = { layers = 6, width = n, label = "width " .. n } end
grids.run(E, {
  model = "phong",
  figures = {
    { file = "figures/fig_4_1_depth.png", title = "Figure 4.1 — Phong, width 6: 8, 12 and 16 hidden layers", nets = depth },
    { file = "figures/fig_4_2_width.png", title = "Figure 4.2 — Phong, 6 hidden layers: width 8, 10 and 16", nets = width },
  },
  table_title = "Figures 4.1 and 4.2 — validation MSE and image MSE on the training and the test mesh",
})

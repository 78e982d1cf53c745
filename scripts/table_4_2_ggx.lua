-- Table 4.2: how well networks of 2..12 hidden layers x 2..12 neurons learn the GGX BRDF (a gold
-- metal; normal + view -> RGB on the cloth mesh), median of 10 seeds of the minimum validation
-- MSE over 20 epochs, beside the thesis' numbers.
--   shadenet scripts/table_4_2_ggx.lua [--quick] [--shard i/n] [--out DIR] [--backend cpu|gl|auto]
package.path = (arg and arg[0] and arg[0]:match("^(.*)/[^/]*$") or ".") .. "/?.lua;" .. package.path
local exp = require "lib.experiment"
local thesis = require "lib.thesis"
local depth_width = require "lib.depth_width"

local E = exp.start("table_4_2_ggx", arg)
depth_width.run(E, {
  model = "ggx",
  thesis = thesis.table_4_2,
  title = "Table 4.2 — GGX metal: median minimum validation MSE by hidden layers and width",
})

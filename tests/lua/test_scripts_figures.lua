-- Image scripts in --quick mode: table 4.3 with figure 4.10, figures 4.1/4.2, 4.4/4.5 and 4.3/4.8. Files
-- exist, figures are real pictures, per-panel MSEs are finite and agree with what they measure.
local C = require "script_check"
local sn = require "shadenet"
local thesis = require "lib.thesis"

-- A figure is an RGB image with something on it: not one flat colour.
local function assert_picture(path, min_w, min_h)
  assert(C.exists(path), path .. " is missing")
  local img = sn.image.load(path)
  local w, h = img:size()
  assert(w >= min_w and h >= min_h, string.format("%s is %dx%d, expected at least %dx%d", path, w, h, min_w, min_h))
  local seen = {}
  local distinct = 0
  for y = 1, h, 7 do
    for x = 1, w, 7 do
      local p = img:get(x, y)
      local key = string.format("%.2f %.2f %.2f", p[1], p[2], p[3])
      if not seen[key] then seen[key] = true distinct = distinct + 1 end
    end
  end
  assert(distinct > 50, path .. " has only " .. distinct .. " distinct colours: not a rendered figure")
end

local dir = C.tmpdir("t43")
C.ok("scripts/table_4_3_widths.lua", { "--quick", "--out", dir })
local rows = C.csv(dir .. "/table.csv")
assert(#rows == 4, "four width layouts")
C.assert_range(rows, "val_mse", 1e-7, 0.05, "table_4_3")
local by = {}
for _, r in ipairs(rows) do by[r.widths] = r end
assert(by["6 fixed"].parameters == 357 and by["13 fixed"].parameters == 1407, "parameter counts of 8x6 and 8x13")
assert(by["6 -> 13"].hidden == "4x6+4x13" and by["13 -> 6"].hidden == "4x13+4x6", "6 -> 13 is 6 on the input side")
for name, t in pairs(thesis.table_4_3) do assert(by[name].thesis_val_mse == t, "thesis value for " .. name) end
assert_picture(dir .. "/figures/fig_4_10_widths.png", 600, 200)
local panels = C.csv(dir .. "/figures/fig_4_10_widths.csv")
assert(#panels == 4, "one MSE per network panel")
C.assert_range(panels, "mse", 1e-7, 0.05, "figure 4.10")
C.assert_range(panels, "non_finite_pixels", 0, 0, "figure 4.10")
C.rm(dir)

-- Figures 4.1/4.2 (Phong): the same grids, with each network's colour shift on the training
-- mesh (the Phong truth is grey, so a shift is the network's own colour: >= 0, and small).
dir = C.tmpdir("f41")
C.ok("scripts/fig_4_1_4_2_phong.lua", { "--quick", "--out", dir })
assert_picture(dir .. "/figures/fig_4_1_depth.png", 600, 300)
assert_picture(dir .. "/figures/fig_4_2_width.png", 600, 300)
rows = C.csv(dir .. "/table.csv")
assert(#rows == 6, "3 networks in each figure")
C.assert_range(rows, "train_mesh_mse", 1e-7, 0.05, "figures 4.1/4.2")
C.assert_range(rows, "colour_shift", 0, 0.1, "figures 4.1/4.2")
local deepest
for _, r in ipairs(rows) do if r.network == "16 layers" then deepest = r end end
assert(deepest and deepest.hidden == "L16-W06", "figure 4.1's 16 hidden layers of width 6")
C.rm(dir)

dir = C.tmpdir("f44")
C.ok("scripts/fig_4_4_4_5_grids.lua", { "--quick", "--out", dir })
assert_picture(dir .. "/figures/fig_4_4_depth.png", 900, 300)
assert_picture(dir .. "/figures/fig_4_5_width.png", 900, 300)
rows = C.csv(dir .. "/table.csv")
assert(#rows == 12, "6 networks in each figure")
C.assert_range(rows, "train_mesh_mse", 1e-7, 0.05, "figures 4.4/4.5")
C.assert_range(rows, "test_mesh_mse", 1e-7, 0.5, "figures 4.4/4.5")
-- Deeper GGX networks fit the training mesh better after the same training (thesis 4.1.2).
local d4, d14
for _, r in ipairs(rows) do
  if r.network == "4 layers" then d4 = r.train_mesh_mse end
  if r.network == "14 layers" then d14 = r.train_mesh_mse end
end
assert(d14 < d4, string.format("14 layers (%.5f) beat 4 layers (%.5f) on the training mesh", d14, d4))
C.rm(dir)

dir = C.tmpdir("f48")
C.ok("scripts/fig_4_8_generalization.lua", { "--quick", "--out", dir })
assert_picture(dir .. "/figures/fig_4_3_phong.png", 300, 300)
assert_picture(dir .. "/figures/fig_4_8_ggx.png", 300, 300)
rows = C.csv(dir .. "/table.csv")
assert(#rows == 8, "2 networks x (1 training view + 2 test views + the unseen meshes' mean)")
for _, r in ipairs(rows) do
  assert(C.finite(r.image_mse) and r.image_mse >= 0 and r.image_mse < 0.2, "image MSE in range: " .. tostring(r.image_mse))
  -- The rendered image agrees with the validation rows on the mesh it learned from.
  if r.mesh == "training mesh" then
    assert(r.image_mse < 20 * r.val_mse + 1e-3, string.format("training-mesh image MSE %.5f vs validation %.5f", r.image_mse, r.val_mse))
  end
end
-- The default data covers the sphere: little of the test mesh lies outside it.
local summary = C.json(dir .. "/run.json").summary
assert(summary.max_train_normal_y > 0.9 and summary.normal_coverage > 0.8 and summary.test_share_outside < 0.05,
       "default data covers the test mesh: " .. summary.normal_coverage .. " " .. summary.test_share_outside)
assert_picture(dir .. "/figures/coverage.png", 1000, 300)
C.rm(dir)
-- The hanging cloth alone: the test mesh faces where the cloth never does (its top).
dir = C.tmpdir("f48c")
C.ok("scripts/fig_4_8_generalization.lua", { "--quick", "--data", "cloth", "--out", dir })
summary = C.json(dir .. "/run.json").summary
assert(summary.max_train_normal_y < 0.9 and summary.test_share_outside > 0.05 and summary.test_share_outside < 0.9,
       "cloth-only coverage: " .. summary.max_train_normal_y .. " " .. summary.test_share_outside)
C.rm(dir)
print("figure scripts: ok")

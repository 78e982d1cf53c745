-- Sections 4.4 (weight edits) and 4.5 (textures) in --quick mode.
local C = require "script_check"
local sn = require "shadenet"
local thesis = require "lib.thesis"

local dir = C.tmpdir("s44")
C.ok("scripts/sec_4_4_weight_edits.lua", { "--quick", "--out", dir })
C.assert_files(dir, { "figures/weight_edits.png", "table.md", "table.csv", "run.json", "networks/fitted.mlp",
                      "networks/last_swap_rb.mlp" })
local rows = C.csv(dir .. "/table.csv")
assert(#rows == 12, "6 edits x 2 meshes")
C.assert_range(rows, "colour_change", 0, 2, "edits")
-- The figure's per-panel MSEs beside it: the fitted network and each edit, on both meshes.
local wpanels = C.csv(dir .. "/figures/weight_edits.csv")
assert(#wpanels == 2 * 7, "fitted + 6 edits on 2 meshes: " .. #wpanels)
C.assert_range(wpanels, "mse", 0, 1, "weight_edits panels")
C.assert_range(rows, "pattern_change", 0, 2, "edits")
local e = {}
for _, r in ipairs(rows) do if r.mesh == "training mesh" then e[r.edit] = r end end
-- The thesis' observation, measured: the last layer recolours without moving the shading;
-- the first layer moves the shading.
assert(e.e.pattern_change < 0.02 and e.e.colour_change > 0.3, "swapping output rows recolours only")
assert(e.a.pattern_change > 10 * e.e.pattern_change and e.b.pattern_change > 10 * e.f.pattern_change,
       "first-layer edits change the pattern far more than last-layer edits")
-- And keep the colours: the bands move, the palette stays (per-pixel chromaticity scored them
-- 0.37 and 0.31, above the green row's recolouring).
assert(e.a.colour_change < 0.1 and e.b.colour_change < 0.1 and e.a.colour_change < e.f.colour_change + 0.05,
       ("first-layer edits keep the palette: %g, %g"):format(e.a.colour_change, e.b.colour_change))
-- The saved networks are the edited ones: the swap's red row is the fitted blue row.
local fitted, swapped = sn.load(dir .. "/networks/fitted.mlp"), sn.load(dir .. "/networks/last_swap_rb.mlp")
local L = #fitted.layers
assert(swapped.layers[L].weight[1][1] == fitted.layers[L].weight[3][1], "saved edit: rows swapped")
assert(swapped.layers[L].bias[3] == fitted.layers[L].bias[1], "saved edit: biases swapped")
-- Figure 4.17: three stylised edits, measured; cycling the output colours recolours most.
assert(C.exists(dir .. "/figures/fig_4_17_styles.png"), "figure 4.17")
local styles = C.csv(dir .. "/figures/fig_4_17_styles.csv")
assert(#styles == 6, "3 styles x 2 meshes")
C.assert_range(styles, "colour_change", 0, 1, "figure 4.17")
C.assert_range(styles, "pattern_change", 0, 2, "figure 4.17")
for _, r in ipairs(styles) do  -- every style changes the look, in colour or in pattern
  assert(r.colour_change + r.pattern_change > 0.01, ("style %s on the %s: %g, %g"):format(r.style, r.mesh, r.colour_change, r.pattern_change))
end
for _, r in ipairs(styles) do
  -- Cycled colours: new colours, the same pattern (luminance correlation called it 0.26 changed).
  if r.style == "b" then
    assert(r.colour_change > 0.3 and r.pattern_change < 0.05, ("cycled colours: %g, %g"):format(r.colour_change, r.pattern_change))
  end
end
-- Figures 4.18/4.19: the 6 x 8 network's edit recolours alike from every view, shading kept.
assert(C.exists(dir .. "/figures/fig_4_18_4_19.png"), "figures 4.18 and 4.19")
local views = C.csv(dir .. "/figures/fig_4_18_4_19.csv")
assert(#views == 4, "the training view and three test-mesh views")
C.assert_range(views, "fitted_mse", 1e-7, 0.05, "figure 4.18")
C.assert_range(views, "colour_change", 0.3, 2, "figure 4.19")
C.assert_range(views, "pattern_change", 0, 0.05, "figure 4.19")
C.rm(dir)

dir = C.tmpdir("s45")
C.ok("scripts/sec_4_5_textures.lua", { "--quick", "--out", dir })
C.assert_files(dir, { "figures/textures.png", "table.md", "table.csv", "run.json" })
rows = C.csv(dir .. "/table.csv")
assert(#rows == 4, "textured Phong, texture, texture frequency-encoded into two networks")
local tpanels = C.csv(dir .. "/figures/textures.csv")
assert(#tpanels == 4, "a per-panel MSE for each row of the textures figure: " .. #tpanels)
for i, p in ipairs(tpanels) do
  assert(math.abs(p.mse - rows[i].image_mse) <= 1e-6 * rows[i].image_mse, "the figure's MSE is the table's image MSE")
  -- One colour scale for every row's heatmap (each row was scaled to its own maximum).
  assert(p.error_scale == tpanels[1].error_scale and p.error_scale > 0, "one error scale: " .. tostring(p.error_scale))
end
C.assert_range(rows, "val_mse", 1e-7, 0.05, "textures")
C.assert_range(rows, "detail_kept", 0, 1.5, "textures")
assert(rows[1].thesis_val_mse == thesis.sec_4_5.textured_phong and rows[2].thesis_val_mse == thesis.sec_4_5.texture_from_position_uv,
       "thesis values beside ours")
for _, r in ipairs(rows) do
  assert(r.val_mse < r.constant_mse, r.case .. ": a fit better than the constant predictor")
end
-- The texture from position + UV comes out blurry: most of its gradient energy is gone.
assert(rows[2].detail_kept < 0.5, "texture detail lost: " .. rows[2].detail_kept)
assert(rows[2].texture_learned == "no", rows[2].texture_learned)
-- Frequency-encoded, the same network draws the checks: a lower image error, the coarse detail kept.
for i = 3, 4 do
  assert(rows[i].encoding:find("frequency"), rows[i].encoding)
  assert(rows[i].image_mse < 0.6 * rows[2].image_mse, ("%s: image MSE %g vs %g unencoded"):format(rows[i].case, rows[i].image_mse, rows[2].image_mse))
  assert(rows[i].coarse_detail_kept > 2 * rows[2].coarse_detail_kept and rows[i].coarse_detail_kept > 0.5,
         rows[i].case .. ": coarse detail " .. rows[i].coarse_detail_kept)
  assert(rows[i].texture_learned ~= "no", rows[i].texture_learned)
end
assert(rows[1].texture_learned == "n/a", "(a) is not a texture case")
C.rm(dir)

-- scripts/stress_lighting.lua takes the shared command line: --quick and --help work, --out
-- without a folder is an error (it used to write to results/ silently).
local sdir = C.tmpdir("stress")
C.ok("scripts/stress_lighting.lua", { "--quick", "--out", sdir })
C.assert_files(sdir, { "table.md", "table.csv" })
local scode, sout = C.run("scripts/stress_lighting.lua", { "--help" })
assert(scode == 0 and sout:find("usage: shadenet scripts/stress_lighting.lua", 1, true), "stress --help:\n" .. sout)
scode, sout = C.run("scripts/stress_lighting.lua", { "--out" })
assert(scode ~= 0 and sout:find("--out needs a value", 1, true), "stress --out without a value:\n" .. sout)
-- The options of training are not its own: --help omits them, and given they are unknown.
local _, help = C.run("scripts/stress_lighting.lua", { "--help" })
assert(not help:find("--shard", 1, true) and not help:find("--backend", 1, true), "stress --help:\n" .. help)
scode, sout = C.run("scripts/stress_lighting.lua", { "--backend", "gl" })
assert(scode == 2 and sout:find("unknown option '--backend' (valid: --quick, --out DIR, --help)", 1, true), sout)
C.rm(sdir)

print("section scripts: ok")

-- table_4_4_color_spaces.lua --quick: 3 spaces x 3 widths; the RGB column is a second,
-- independent measurement (compute-shader forward pass + decoding in Lua) of what training
-- reported, so for RGB networks the two must agree.
local C = require "script_check"
local thesis = require "lib.thesis"

local dir = C.tmpdir("t44")
C.ok("scripts/table_4_4_color_spaces.lua", { "--quick", "--out", dir })
local rows = C.csv(dir .. "/table.csv")
assert(#rows == 9, "RGB, HSV, CIE x widths 4, 8, 16")
C.assert_range(rows, "val_mse", 1e-7, 0.1, "table_4_4")
C.assert_range(rows, "rgb_val_mse", 1e-7, 0.1, "table_4_4")
for _, r in ipairs(rows) do
  local key = r.space == "RGB" and "rgb" or r.space == "HSV" and "hsv" or "cie"
  assert(r.thesis_val_mse == thesis.table_4_4[key][r.width], "thesis value for " .. r.space .. " " .. r.width)
  if r.space == "RGB" then
    assert(math.abs(r.rgb_val_mse - r.val_mse) <= 1e-4 * r.val_mse,
           string.format("RGB width %d: forward pass %.9g vs training %.9g", r.width, r.rgb_val_mse, r.val_mse))
  end
end
local md = C.read(dir .. "/table.md")
assert(md:find("the same networks' validation MSE in RGB", 1, true), "both grids in table.md")
-- Figure 4.12: seed 1's networks of widths 4 and 16 in each space, each with its colour shift
-- against the (gold, so coloured) truth; width 8 is not in the figure.
assert(C.exists(dir .. "/figures/fig_4_12_color_spaces.png"), "figure 4.12")
local panels = C.csv(dir .. "/figures/fig_4_12_color_spaces.csv")
assert(#panels == 6, "3 spaces x widths 4 and 16: " .. #panels)
C.assert_range(panels, "colour_shift", 0, 0.3, "figure 4.12")
for _, r in ipairs(rows) do
  local shown = r.width == 4 or r.width == 16
  assert((tonumber(r.colour_shift) ~= nil) == shown, r.space .. " width " .. r.width .. ": colour shift only for the figure's networks")
end
C.rm(dir)
print("table_4_4 script: ok")

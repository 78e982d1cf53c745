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
C.rm(dir)
print("table_4_4 script: ok")

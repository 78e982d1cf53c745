-- Image functions at their edges (issue 13's findings): heatmaps of images 1-3 pixels tall used
-- to abort the process inside OpenImageIO; sn.image.mse read outside the mask with
-- mask_channel = 0 (silently wrong) and crashed with a negative one.
local sn = require "shadenet"

for _, h in ipairs { 1, 2, 3 } do
  local img = sn.image.new { width = 5, height = h, channels = 4, fill = 0.25 }
  local heat = sn.image.heatmap(img, { label = "|error|", max = 0.5 })
  local w, hh = heat:size()
  assert(w > 5 and hh >= h, ("a %d-pixel-tall heatmap: %dx%d"):format(h, w, hh))
  local p = heat:get(1, hh)  -- the image's last row sits at the bottom, under the label
  assert(p[1] >= 0 and p[1] <= 1, "a colour")
end

local a = sn.image.new { width = 4, height = 4, channels = 4, fill = 0.5 }
for _, case in ipairs { { { mask = a, mask_channel = 0 }, "mask channel 0 outside the mask's channels 1..4" },
                        { { mask = a, mask_channel = -3 }, "mask channel -3 outside the mask's channels 1..4" },
                        { { mask = a, mask_channel = 5 }, "mask channel 5 outside the mask's channels 1..4" },
                        { { channels = 0 }, "'channels' must be 1..4 (or all)" } } do
  local ok, err = pcall(sn.image.mse, a, a, case[1])
  assert(not ok and err:find(case[2], 1, true), tostring(err))
end
print("ok")

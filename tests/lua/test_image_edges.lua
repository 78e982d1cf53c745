-- Image functions at their edges (issue 13's findings): heatmaps of images 1-3 pixels tall used
-- to abort the process inside OpenImageIO; sn.image.mse read outside the mask with
-- mask_channel = 0 (silently wrong) and crashed with a negative one. Saving: a PNG writes NaN as 0
-- and +inf as full brightness (inf was 0, the darkest), and Radiance HDR, which holds RGB alone,
-- takes an image of 4 channels (alpha dropped) or 1 (grey to all three); it refused both. Colour
-- under alpha < 1 comes back as it was saved.
local sn = require "shadenet"
local C = require "script_check"

for _, h in ipairs { 1, 2, 3 } do
  local img = sn.image.new { width = 5, height = h, channels = 4, fill = 0.25 }
  local heat = sn.image.heatmap(img, { label = "|error|", max = 0.5 })
  local w, hh = heat:size()
  assert(w > 5 and hh >= h, ("a %d-pixel-tall heatmap: %dx%d"):format(h, w, hh))
  local p = heat:get(1, hh)  -- the image's last row sits at the bottom, under the label
  assert(p[1] >= 0 and p[1] <= 1, "a colour")
end

local a = sn.image.new { width = 4, height = 4, channels = 4, fill = 0.5 }
for _, case in ipairs { { { mask = a, mask_channel = 0 }, "option 'mask_channel' must be 1..4 (the mask's channels), got 0" },
                        { { mask = a, mask_channel = -3 }, "option 'mask_channel' must be 1..4 (the mask's channels), got -3" },
                        { { mask = a, mask_channel = 5 }, "option 'mask_channel' must be 1..4 (the mask's channels), got 5" },
                        { { channels = 0 }, "option 'channels' must be 1..4 (the image's channels), got 0" },
                        { { channels = 9 }, "option 'channels' must be 1..4 (the image's channels), got 9" } } do
  for _, f in ipairs { sn.image.mse, sn.image.ssim } do
    local ok, err = pcall(f, a, a, case[1])
    assert(not ok and err:find(case[2], 1, true), tostring(err))
  end
end
-- By default the colour channels are compared, not alpha (coverage): it was, and a channel
-- count past the image's (9) meant all of them.
local half = sn.image.new { width = 16, height = 16, channels = 4, fill = 0.5 }
local checker = sn.image.new { width = 16, height = 16, channels = 4, fill = 0.5 }
for y = 1, 16 do for x = 1, 16 do checker:set(x, y, { 0.5, 0.5, 0.5, (x + y) % 2 }) end end
assert(sn.image.mse(half, checker) == 0 and sn.image.ssim(half, checker) == 1, "alpha not compared by default")
assert(sn.image.mse(half, checker, { channels = 4 }) == 0.0625, "alpha compared when asked for")
-- A NaN compared is an error naming it, in sn.image.mse as in sn.image.ssim, not a NaN to carry
-- on with; outside the channels or the mask compared it does not count.
local g = sn.image.new { width = 16, height = 16, channels = 4, fill = 0.5 }
local n = sn.image.new { width = 16, height = 16, channels = 4, fill = 0.5 }
n:set(3, 2, { 0.5, 0 / 0, 0.5, 1 })
for f, text in pairs { [sn.image.mse] = "sn.image.mse: image 2", [sn.image.ssim] = "ssim" } do
  local ok, err = pcall(f, g, n)
  assert(not ok and err:find(text .. ": pixel (3, 2) channel 2 is not a finite number", 1, true), tostring(err))
  -- An infinity too (mse gave inf).
  local inf = sn.image.new { width = 16, height = 16, channels = 4, fill = 0.5 }
  inf:set(5, 6, { 0.5, 0.5, -1 / 0, 1 })
  ok, err = pcall(f, g, inf)
  assert(not ok and err:find(text .. ": pixel (5, 6) channel 3 is not a finite number", 1, true), tostring(err))
end
assert(sn.image.mse(g, n, { channels = 1 }) == 0, "channel 2 not compared")
n:set(3, 2, { 0.5, 0 / 0, 0.5, 0 })
-- (a mask of its own: n's alpha of 0.5 covers no pixel, which mse now refuses too)
local mask = sn.image.new { width = 16, height = 16, channels = 4, fill = 1 }
mask:set(3, 2, { 1, 1, 1, 0 })
assert(sn.image.mse(g, n, { mask = mask }) == 0, "the pixel outside the mask")
local dir = C.tmpdir("image_edges")
local img = sn.image.new { width = 2, height = 1 }
img:set(1, 1, { 1 / 0, 0 / 0, -1 / 0, 1 })
img:set(2, 1, { 3.5, 0.25, 0.75, 1 })
img:save(dir .. "/edges.png")
local png = sn.image.load(dir .. "/edges.png")
assert(table.concat(png:get(1, 1), " ") == "1 0 0 1", "inf, NaN, -inf: " .. table.concat(png:get(1, 1), " "))
img:set(1, 1, { 1, 2, 3, 0.5 })
img:save(dir .. "/rgba.hdr")
local hdr = sn.image.load(dir .. "/rgba.hdr")
assert(select(3, hdr:size()) == 3, "HDR holds RGB")
for x, want in ipairs { { 1, 2, 3 }, { 3.5, 0.25, 0.75 } } do
  for c = 1, 3 do  -- RGBE keeps 8 bits of mantissa per channel
    assert(math.abs(hdr:get(x, 1)[c] - want[c]) <= want[c] / 64, ("hdr %d,1 channel %d: %g"):format(x, c, hdr:get(x, 1)[c]))
  end
end
-- Colour under alpha is kept as it is (unassociated), in the file and back: it was divided by
-- alpha on writing (clamped at 1) and multiplied on reading, so (1, 0.25, 0.75) at alpha 0.5 came
-- back as (0.5, 0.25, 0.5) and colour at alpha 0 as black.
local seen = sn.image.new { width = 2, height = 1 }
seen:set(1, 1, { 1, 0.25, 0.75, 0.5 })
seen:set(2, 1, { 0.2, 0.4, 0.6, 0 })
for _, ext in ipairs { "png", "tif", "exr" } do
  seen:save(dir .. "/alpha." .. ext)
  local back = sn.image.load(dir .. "/alpha." .. ext)
  for x = 1, 2 do
    for c = 1, 4 do
      local want, got = seen:get(x, 1)[c], back:get(x, 1)[c]
      assert(math.abs(got - want) <= 0.5 / 255 + 1e-6, ("%s pixel %d channel %d: %g, saved %g"):format(ext, x, c, got, want))
    end
  end
end
local grey = sn.image.new { width = 1, height = 1, channels = 1, fill = 0.75 }
grey:save(dir .. "/grey.hdr")
assert(table.concat(sn.image.load(dir .. "/grey.hdr"):get(1, 1), " ") == "0.75 0.75 0.75", "grey to all three")
-- RGBE holds no negative or non-finite value: its encoder turned -0.375 into 0.625 and a pixel
-- with a NaN or Inf black; now they are 0 (+Inf the largest it holds) and the rest stays.
local odd = sn.image.new { width = 3, height = 1, channels = 3 }
odd:set(1, 1, { 0.5, -0.375, 0.25 })
odd:set(2, 1, { 0 / 0, 0.5, 0.5 })
odd:set(3, 1, { 1 / 0, -1 / 0, 0 })
odd:save(dir .. "/odd.hdr")
local back = sn.image.load(dir .. "/odd.hdr")
assert(table.concat(back:get(1, 1), " ") == "0.5 0 0.25", "negative to 0: " .. table.concat(back:get(1, 1), " "))
assert(table.concat(back:get(2, 1), " ") == "0 0.5 0.5", "NaN to 0, the rest kept: " .. table.concat(back:get(2, 1), " "))
assert(back:get(3, 1)[1] > 1e37 and back:get(3, 1)[2] == 0, "+Inf to the largest, -Inf to 0")
-- Grey and alpha in a format without alpha: grey, alpha dropped (a JPEG held (grey, alpha, 0)).
local ga = sn.image.new { width = 8, height = 8, channels = 2 }
for y = 1, 8 do for x = 1, 8 do ga:set(x, y, { 0.8, 0.2 }) end end
for _, ext in ipairs { "jpg", "bmp" } do
  ga:save(dir .. "/ga." .. ext)
  local g2 = sn.image.load(dir .. "/ga." .. ext)
  assert(select(3, g2:size()) == 1 and math.abs(g2:get(4, 4)[1] - 0.8) < 0.01, ext .. ": " .. table.concat(g2:get(4, 4), " "))
end
-- A truncated file is refused, whatever its format: libjpeg filled a cut JPEG's missing rows
-- with grey and the image loaded whole, without a word.
local noisy = sn.image.new { width = 64, height = 64, channels = 3 }
for y = 1, 64 do for x = 1, 64 do noisy:set(x, y, { (x * 7 % 13) / 13, (y * 5 % 11) / 11, ((x + y) % 7) / 7 }) end end
for _, ext in ipairs { "jpg", "png" } do
  local whole = noisy:save(dir .. "/whole." .. ext)
  local bytes = sn.fs.read(whole)
  sn.fs.write(dir .. "/cut." .. ext, bytes:sub(1, math.floor(#bytes * 0.7)))
  local ok, err = pcall(sn.image.load, dir .. "/cut." .. ext)
  assert(not ok and tostring(err):find("cut." .. ext, 1, true), ext .. ": a truncated file loaded")
  assert(sn.image.load(whole):size() == 64, ext .. ": the whole file loads")
end
C.rm(dir)
print("ok")

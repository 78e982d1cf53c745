-- What the window shows over the side view (SHADENET_LIVE_SHOWN): the panels' labels where the
-- panels start (truth top-left, network top-right, the error under the truth), the heatmap's
-- colour bar in the fourth panel (black to yellow, left to right), and the frame-time counter in
-- the top-right corner; the rest of the picture is the view itself, untouched. The probe (key I)
-- draws a cross-hair and the values under the cursor, and follows it.
local sn = require "shadenet"
package.path = "tests/live/?.lua;" .. package.path
local H = require "harness"

local dir = "out/live_tests/hud"
local script = H.scenario(dir)

local W, Hh = 320, 240
local s = H.start { dir = dir .. "/session", script = script, size = W .. "x" .. Hh, shown = true }
s:wait_frame(1)
s:send("sn.live.set_view{ mode = 'side' }")
local frame = s:image(s:settle())
local pw, ph = W / 2, Hh / 2

local function same(a, b)  -- alpha too: a label over the transparent background changes only it
  for c = 1, 4 do if math.abs(a[c] - b[c]) > 1e-6 then return false end end
  return true
end
-- The newest picture shown over this frame (a present of the frame before may come first).
local shown
for _ = 1, 300 do
  local _, img = s:shown()
  if img and same(img:get(pw / 2, ph / 2 + 10), frame:get(pw / 2, ph / 2 + 10))
     and same(img:get(pw + pw / 2, ph / 2 + 10), frame:get(pw + pw / 2, ph / 2 + 10)) then
    shown = img
    break
  end
  H.sleep(0.05)
end
assert(shown, "a picture of the side view was shown")
local w, h = shown:size()
assert(w == W and h == Hh, ("the shown picture is the window's size: %dx%d"):format(w, h))

-- Counts pixels in a rectangle (1-based, inclusive) that differ from the view and that are
-- near-white text.
local function region(x0, y0, x1, y1)
  local changed, white = 0, 0
  for y = y0, y1 do
    for x = x0, x1 do
      local p = shown:get(x, y)
      if not same(p, frame:get(x, y)) then changed = changed + 1 end
      if p[1] > 0.85 and p[2] > 0.85 and p[3] > 0.85 then white = white + 1 end
    end
  end
  return changed, white
end

local labels = {
  { "truth", 1, 1, 30, 14 },
  { "network", pw + 1, 1, pw + 40, 14 },
  { "|error|", 1, ph + 1, 40, ph + 14 },
  { "counter", W - 40, 1, W, 14 },
}
for _, l in ipairs(labels) do
  local changed, white = region(l[2], l[3], l[4], l[5])
  local area = (l[4] - l[2] + 1) * (l[5] - l[3] + 1)
  assert(changed > area * 0.9 and white > 10,
         ("the %s label is drawn at (%d,%d): %d of %d pixels changed, %d white"):format(l[1], l[2], l[3], changed, area, white))
end
-- Between the labels the view shows through: the middle of each picture panel is untouched.
for _, p in ipairs { { pw / 2, ph / 2 }, { pw + pw / 2, ph / 2 + 20 }, { pw / 2, ph + ph / 2 } } do
  assert(same(shown:get(p[1], p[2]), frame:get(p[1], p[2])), ("pixel (%d,%d) is the view's"):format(p[1], p[2]))
end
-- The truth label is where the truth panel starts, not over the network panel's top-left.
local _, white_mid = region(60, 1, pw - 10, 18)
assert(white_mid == 0, "no label text between the truth and network labels: " .. white_mid)

-- The colour bar: a row in the fourth panel's lower part runs from black to inferno's yellow.
local bar_y
for y = h - 1, ph + 1, -1 do
  local right = shown:get(W - 10, y)
  if right[1] > 0.9 and right[2] > 0.8 and right[3] < 0.7 then bar_y = y break end
end
assert(bar_y, "the colour bar's yellow end is in the fourth panel")
local left, mid = shown:get(pw + 10, bar_y), shown:get(pw + pw / 2, bar_y)
assert(left[1] + left[2] + left[3] < 0.2, ("the bar starts black: %g %g %g"):format(left[1], left[2], left[3]))
assert(mid[1] > 0.5 and mid[3] > mid[2], ("its middle is inferno's red-purple: %g %g %g"):format(mid[1], mid[2], mid[3]))

-- The counter follows the frame time: the title's ms is the counter's, so the two agree on
-- how long the frame took (the title ends "N.N ms").
local title = H.window_title("live test")
assert(title and title:find("side") and title:find("%d+%.%d ms$"), "the title has the frame time: " .. tostring(title))

-- The probe (key I): a cross-hair on the pixel under the cursor and a box of its values beside
-- it, following the cursor; the labels stay.
local x11 = H.x11()
local cx, cy = 60, 50  -- in the truth panel (the window sits at the screen's top-left)
x11:move(cx, cy)
local n0 = s:shown()
x11:key("i")
local probed
for _ = 1, 200 do
  local n, img = s:shown()
  if n > n0 and img then
    local arm = img:get(cx + 1, cy + 1 - 4)  -- the cross-hair's upper arm (1-based pixels)
    if arm[1] > 0.95 and arm[2] > 0.95 then probed = img break end
  end
  H.sleep(0.05)
end
assert(probed, "the cross-hair is drawn on the pixel under the cursor")
shown = probed
local changed, white = region(cx + 14, cy + 14, cx + 60, cy + 40)
assert(changed > 500 and white > 30, ("the probe's box is beside the pixel: %d changed, %d white"):format(changed, white))
assert(same(probed:get(cx + 1, cy + 1), frame:get(cx + 1, cy + 1)), "the probed pixel itself stays visible")
-- Moved: the box follows (a box now at the new place, none at the old).
x11:move(cx + 100, cy + 100)
local moved
for _ = 1, 200 do
  local _, img = s:shown()
  local arm = img:get(cx + 101, cy + 101 - 4)
  if arm[1] > 0.95 and arm[2] > 0.95 then moved = img break end
  H.sleep(0.05)
end
assert(moved, "the probe follows the cursor")
shown = moved
local old_changed = region(cx + 14, cy + 14, cx + 60, cy + 40)
assert(old_changed == 0, "no box left at the old place: " .. old_changed)
x11:close()
s:stop()

-- A render size smaller than the window (sn.live.show{ size = ... }, advised on llvmpipe): the
-- picture is fitted into the window and the overlays are drawn at the window's size over it,
-- not at the render's and magnified with it (the error box and the labels ran off the window).
local small = dir .. "/small.lua"
H.write(small, (H.read("tests/live/scenario.lua"):gsub('title = "live test",', 'title = "live test", size = { 80, 60 },')))
local s2 = H.start { dir = dir .. "/small_session", script = small, size = W .. "x" .. Hh, shown = true }
s2:wait_frame(1)
s2:send("sn.live.set_view{ mode = 'side' }")
s2:settle()
local side
for _ = 1, 300 do
  local _, img = s2:shown()
  if img then
    local lw, lh = img:size()
    if lw == W and lh == Hh then
      shown = img
      local _, white = region(pw + 1, 1, pw + 40, 14)  -- "network", at the window's size
      if white > 10 then side = img break end
    end
  end
  H.sleep(0.05)
end
assert(side, "the side view's labels are drawn at the window's size over the 80 x 60 picture")
local _, tall = region(pw + 1, 16, pw + 40, 40)  -- a label magnified 4 times reached down here
assert(tall == 0, "the network label is not magnified: " .. tall .. " white pixels under it")
s2:stop()
print(("hud: labels at truth (1,1), network (%d,1), error (1,%d), colour bar at row %d, counter top-right; title %s")
      :format(pw + 1, ph + 1, bar_y, title))

-- Errors show inside the picture: an overlay with the message's file:line and the offending
-- source line over the bottom of the last good picture (the rest of it unchanged), the same
-- text on the terminal, gone with the next good save. Headless `--watch` with SHADENET_LIVE_SHOWN
-- (the pictures the window would show, overlays included).
local sn = require "shadenet"
package.path = "tests/live/?.lua;" .. package.path
local H = require "harness"

local dir = "out/live_tests/overlay"
os.execute(("rm -rf %q && mkdir -p %q"):format(dir, dir))
local template = H.read("tests/live/scenario.lua")
H.write(dir .. "/tint.frag", H.read("tests/live/tint.frag"))
local script = dir .. "/scenario.lua"
H.write(script, template)

local s = H.start { dir = dir .. "/session", script = script, window = false, shown = true }
s:wait_frame(1)
local frame = s:image(s:settle())
-- (the first training showed its progress bar over a blank picture: wait for the picture itself)
local n0, clean
for _ = 1, 200 do
  n0, clean = s:shown()
  if clean and H.same(clean, frame) then break end
  H.sleep(0.05)
end
assert(clean and H.same(clean, frame), "without an error the window shows the picture itself")
local w, h = clean:size()

local function same_rows(a, b, y0, y1)
  for y = y0, y1 do
    for x = 1, w, 7 do
      local p, q = a:get(x, y), b:get(x, y)
      for c = 1, 3 do if p[c] ~= q[c] then return false, x, y end end
    end
  end
  return true
end

-- A syntax error: the overlay names scenario.lua:LINE and prints the line.
local edit_line
local i = 0
for l in template:gmatch("[^\n]*\n") do
  i = i + 1
  if l:find("%-%- EDITS") then edit_line = i end
end
H.write(script, (template:gsub("%-%- EDITS\n", "net.layers[1].weight[1][1] = = 0.9\n")))
s:wait_log("%[live%] error: [^\n]*scenario%.lua:" .. edit_line .. ": unexpected symbol near '='\n  " .. edit_line ..
           " | net%.layers%[1%]%.weight%[1%]%[1%] = = 0%.9\n")
-- The newest picture shown once the error is in (a redraw already under way may come first).
local function wait_until(ok, what)
  for _ = 1, 300 do
    local n, img = s:shown()
    if img and ok(img) then return n, img end
    H.sleep(0.05)
  end
  s:fail("no picture shown " .. what)
end
local n1, broken = wait_until(function(img) local p = img:get(3, h - 2) return p[1] > 0.15 end, "with the overlay")
local bottom = broken:get(3, h - 2)
assert(bottom[1] > 0.15 and bottom[1] > 3 * bottom[3], ("the overlay's red box is at the bottom: %g %g %g"):format(
  bottom[1], bottom[2], bottom[3]))
assert(same_rows(broken, clean, 1, math.floor(h / 2)), "the last good picture stays above the overlay")
assert(not same_rows(broken, clean, h - 40, h), "the overlay covers the bottom")
-- Its text: white glyphs in the box (the source line), not only the red background.
local white = 0
for y = h - 60, h do
  for x = 1, w do
    local p = broken:get(x, y)
    if p[1] > 0.9 and p[2] > 0.9 and p[3] > 0.9 then white = white + 1 end
  end
end
assert(white > 50, "the overlay has text, got " .. white .. " white pixels")

-- The next good save clears it: what is shown is the picture again.
H.write(script, template)
s:wait_log("%[live%] fixed")
local _, fixed = wait_until(function(img) return H.same(img, clean) end, "without the overlay after the good save")
s:stop()
print(("overlay: scenario.lua:%d shown over the bottom of a %dx%d picture (%d white text pixels), cleared by the fix"):format(
  edit_line, w, h, white))

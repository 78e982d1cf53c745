-- Under Xvfb: --window opens a window, renders, and what it reads back equals the headless
-- render of the same scene (same offscreen path; the window only presents).
local sn = require "shadenet"
assert(sn.windowed(), "this test runs with --window")
package.path = "tests/window/?.lua;" .. package.path
local scene = require "render_scene"

local w, h = sn.window_size()
assert(w > 0 and h > 0, "window has no framebuffer")
local target = scene.render(w, h)
local windowed = target:read()
local shown = sn.screenshot(target)   -- what the window displays (8-bit framebuffer)

os.execute("mkdir -p out/window_test")
local ref_path = "out/window_test/headless.exr"
local cmd = ("%q tests/window/render_scene.lua %d %d %s"):format(arg[-1], w, h, ref_path)
assert(os.execute(cmd) == 0, "headless reference render failed: " .. cmd)
local headless = sn.image.load(ref_path)

-- 1. the offscreen render is bit-identical in both modes
local covered = 0
for y = 1, h, 3 do
  for x = 1, w, 3 do
    local a, b = windowed:get(x, y), headless:get(x, y)
    for c = 1, 4 do
      assert(a[c] == b[c], ("pixel (%d,%d) channel %d: window %.9g vs headless %.9g"):format(x, y, c, a[c], b[c]))
    end
    if a[4] > 0.5 then covered = covered + 1 end
  end
end
assert(covered > 1000, "the sphere covers too few pixels: " .. covered)

-- 2. the window shows that image (8 bits per channel)
local sw, sh = shown:size()
assert(sw == w and sh == h, ("screenshot %dx%d, window %dx%d"):format(sw, sh, w, h))
assert(sn.image.mse(shown, headless, { channels = 3 }) < 1e-5, "window content differs from the render")
print(("window %dx%d: %d sampled covered pixels equal the headless render"):format(w, h, covered))

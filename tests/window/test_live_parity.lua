-- Headless parity: for every view mode, a moved camera, a moved light and a heatmap scale changed
-- with the [ and ] keys, the frame the window showed is bit for bit the image sn.live.render makes
-- headless (EGL, no display) from the view the window reports (sn.live.view_code). (The line left
-- the scale out: after ] ] its error view was another picture.)
local sn = require "shadenet"
package.path = "tests/live/?.lua;" .. package.path
local H = require "harness"

local dir = "out/live_tests/parity"
local script = H.scenario(dir)

local s = H.start { dir = dir, script = script, size = "180x120" }
s:wait_frame(1)
-- The heatmap scale is set after the line with the [ and ] keys.
local cases = {
  { "network", "sn.live.set_view{ mode = 'network' }" },
  { "truth", "sn.live.set_view{ mode = 'truth' }" },
  { "error", "sn.live.set_view{ mode = 'error' }" },
  { "side", "sn.live.set_view{ mode = 'side' }" },
  { "orbit", "sn.live.set_view{ mode = 'error', camera = sn.camera { eye = { -2, 1.2, 1.5 }, fov = 40 } }" },
  { "light", "sn.live.set_view{ mode = 'truth', light = { dir = { -0.6, 0.2, 0.7 } } }" },
  { "error_scale_1", "sn.live.set_view{ mode = 'error' }", 1 },
  { "side_scale_0.5", "sn.live.set_view{ mode = 'side' }", 0.5 },
  { "network_scale_0.5", "sn.live.set_view{ mode = 'network' }", 0.5 },
}
local x11 = H.x11()
x11:move(90, 60)
-- Presses ] or [ until the window's last frame has the heatmap scale `want`, one key at a time
-- (keys go to the window, lines to the console: which comes first is not known; and XTest keys
-- have been seen to go missing under Xvfb).
local asked = 0
local function scale_reaches(want)
  for _ = 1, 40 do
    asked = asked + 1
    s:send(("print('SCALE %d ' .. sn.live.view().error_scale)"):format(asked))
    local now = tonumber(s:wait_log(("SCALE %d (%%S+)\n"):format(asked)))
    if now == want then return end
    x11:key(now < want and "bracketright" or "bracketleft")
    H.sleep(0.3)
  end
  s:fail("the heatmap scale never became " .. want)
end
local code, frames = { "local sn = require 'shadenet'", ("dofile(%q)"):format(script) }, {}
for i, c in ipairs(cases) do
  s:send(c[2])
  if c[3] then scale_reaches(c[3]) end
  frames[i] = s:settle()
  s:send(('print("VIEW %d " .. sn.live.view_code(%q))'):format(i, dir .. "/headless_" .. c[1] .. ".exr"))
  code[#code + 1] = s:wait_log(("VIEW %d ([^\n]+)"):format(i))
end
s:stop()
x11:close()
code[#code + 1] = "print('HEADLESS OK')"
H.write(dir .. "/headless.lua", table.concat(code, "\n") .. "\n")
H.run_headless(dir .. "/headless.lua", "HEADLESS OK")

local sizes = {}
for i, c in ipairs(cases) do
  local shown, headless = s:image(frames[i]), sn.image.load(dir .. "/headless_" .. c[1] .. ".exr")
  assert(H.same(shown, headless), c[1] .. ": the window's frame differs from the headless render")
  local w, h = shown:size()
  sizes[#sizes + 1] = ("%s %dx%d"):format(c[1], w, h)
end
-- The views really differ from each other (a parity test of identical pictures proves little).
for i = 1, #cases do
  for j = i + 1, #cases do
    local a, b = s:image(frames[i]), s:image(frames[j])
    local wa, ha = a:size()
    local wb, hb = b:size()
    assert(wa ~= wb or ha ~= hb or not H.same(a, b), cases[i][1] .. " and " .. cases[j][1] .. " look the same")
  end
end
-- Without --watch, a --window script that declared a view keeps its window open on it (no
-- reloads, no console): its first frame is the live session's first frame.
local vdir = dir .. "/view_only"
os.execute(("rm -rf %q && mkdir -p %q"):format(vdir, vdir))
local p = io.popen(("SHADENET_LIVE_SNAPSHOT=%q SHADENET_LIVE_EXIT_AFTER=1 %q --window --size 180x120 %q 2>&1 < /dev/null")
                   :format(vdir .. "/frame-%d.exr", H.shadenet, script))
local out = p:read("*a")
p:close()
assert(H.exists(vdir .. "/frame-1.exr"), "the view-only window drew no frame:\n" .. out)
assert(H.same(sn.image.load(vdir .. "/frame-1.exr"), s:image(1)), "the view-only window shows the same first frame")
print("parity: " .. table.concat(sizes, ", ") .. " equal headless; --window without --watch shows the view")

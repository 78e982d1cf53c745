-- The pixel probe: sn.live.probe(x, y) gives the truth, the network and their error at a pixel of
-- the view, equal to the pixels of the rendered pictures (side mode: a pixel of any panel names
-- the same point of all three); in a `--watch` session it reads the window's last frame back
-- instead of drawing again.
local sn = require "shadenet"
package.path = "tests/live/?.lua;" .. package.path
local H = require "harness"
local live = sn.live

local fails = require("expect").fails

local sphere = sn.mesh.sphere { segments = 32, rings = 16 }
local normals = sn.program { vertex = "mesh.vert", fragment = "normals.frag" }
local calls = { network = 0, truth = 0 }
local function drawer(which, tint)
  return function(view)
    calls[which] = calls[which] + 1
    local t = sn.target { width = view.width, height = view.height }
    sn.draw { target = t, program = normals, mesh = sphere, camera = view.camera, clear = { tint, 0, 0, 1 } }
    return t
  end
end
live.show { network = drawer("network", 0.25), truth = drawer("truth", 0), camera = sn.camera { eye = { 0.5, 0.6, 2.8 } },
            size = { 60, 40 } }
local n_img = live.render { mode = "network" }:read()
local t_img = live.render { mode = "truth" }:read()

local function near(a, b, what)
  for c = 1, 3 do
    assert(math.abs(a[c] - b[c]) < 1e-6, ("%s channel %d: %g, expected %g"):format(what, c, a[c], b[c]))
  end
end
local checked = 0
for _, p in ipairs { { 1, 1 }, { 30, 20 }, { 22, 14 }, { 41, 27 }, { 60, 40 } } do
  local t, n, e = live.probe(p[1], p[2])
  near(t, t_img:get(p[1], p[2]), ("truth at (%d,%d)"):format(p[1], p[2]))
  near(n, n_img:get(p[1], p[2]), ("network at (%d,%d)"):format(p[1], p[2]))
  local want = {}
  for c = 1, 3 do want[c] = math.abs(n[c] - t[c]) end
  near(e, want, "error")
  assert(math.abs(e.mean - (want[1] + want[2] + want[3]) / 3) < 1e-9, "the mean error is the heatmap's value")
  checked = checked + 1
end
-- The background differs by the network's red tint only: the probe sees it.
local _, _, e = live.probe(1, 1)
assert(math.abs(e[1] - 0.25) < 1e-6 and e[2] == 0 and e.mean > 0.08, "the background's error is 0.25 in red")
-- The sphere's middle shows its normal (not the background): a pixel, not a constant.
local t_mid = live.probe(30, 20)
assert(math.abs(t_mid[3] - 0.5) > 0.1, "the probe at the middle reads the sphere")

-- Side mode: panels of 30 x 20; pixel (30 + 22, 14) of the network panel is pixel (22, 14).
live.show { network = drawer("network", 0.25), truth = drawer("truth", 0), camera = sn.camera { eye = { 0.5, 0.6, 2.8 } },
            size = { 60, 40 }, mode = "side" }
local pn = live.render { mode = "network", width = 30, height = 20 }:read()
local a_t, a_n = live.probe(22, 14)
local b_t, b_n = live.probe(30 + 22, 14)
near(a_n, pn:get(22, 14), "side: the truth panel's pixel probes the panel's point")
near(b_n, a_n, "side: the network panel's pixel names the same point")
near(b_t, a_t, "side: the same truth")

fails(function() live.probe(61, 1) end, "pixel (61, 1) is outside the 60x40 view (x 1..60, y 1..40)")
fails(function() live.probe(1.5, 1) end, "x and y must be whole pixel numbers")
live.show { truth = drawer("truth", 0), size = { 8, 8 } }
local only_t, no_n, no_e = live.probe(4, 4)
assert(only_t and no_n == nil and no_e == nil, "a show without a network probes the truth alone")

-- target:pixel is one pixel of target:read.
local tgt = live.render { mode = "truth" }
assert(tgt:pixel(5, 3)[1] == tgt:read():get(5, 3)[1], "target:pixel = target:read():get")
fails(function() tgt:pixel(9, 1) end, "outside the 8x8 target")

-- A `--watch` session: the console's probe reads the frame the window drew (the network drawer
-- is not called again) and draws the truth once for it; the values are the frame's.
local dir = "out/live_tests/probe"
os.execute(("mkdir -p %q"):format(dir))
H.write(dir .. "/main.lua", [[
local sn = require "shadenet"
calls = { network = 0, truth = 0 }
local function flat(which, c)
  return function(view)
    calls[which] = calls[which] + 1
    local t = sn.target { width = view.width, height = view.height }
    t:clear(c)
    return t
  end
end
sn.live.show { network = flat("network", { 0.6, 0.3, 0.2, 1 }), truth = flat("truth", { 0.5, 0.3, 0.25, 1 }),
               size = { 6, 4 } }
]])
local s = H.start { dir = dir .. "/session", script = dir .. "/main.lua", window = false }
s:wait_frame(1)
s:settle()
-- Both probes on one console line, so no frame can come between them (each line that runs may
-- be followed by a redraw).
s:send('local t, n, e = sn.live.probe(3, 2) print(("PROBE %.3f %.3f %.3f | %.3f | %.4f | %d %d"):format('
       .. 'n[1], n[2], n[3], t[3], e.mean, calls.network, calls.truth)) '
       .. 'sn.live.probe(6, 4) print(("AGAIN %d %d"):format(calls.network, calls.truth))')
local line = s:wait_log("PROBE ([^\n]+)")
local again = s:wait_log("AGAIN ([^\n]+)")
local frames = tonumber(s:log():match("SETTLE 1 (%d+)")) + 1
s:stop()
assert(line:find("^0%.600 0%.300 0%.200 | 0%.250 | 0%.0500 | "), "the probe's values: " .. line)
local nc, tc = line:match("| (%d+) (%d+)$")
assert(tonumber(nc) == frames and tonumber(tc) == 1,
       ("the network was drawn once per frame (%d frames), not again for the probe: %s"):format(frames, line))
assert(again == nc .. " 1", "a second probe of the frame draws nothing: " .. again)
print(("probe: %d pixels = the pictures', side panels map to one point, --watch reads the frame back (%s)"):format(
  checked, line))

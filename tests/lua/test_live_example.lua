-- examples/live_edit.lua does what docs/live-mode.md says: run plainly it trains the toon
-- network once and saves its four views; the network is close to the truth; each edit line of
-- its edit block (commented out) is valid Lua that changes the picture, and the kept network
-- comes back untouched. The sweep of section 6, typed at the console of a --watch session of the
-- example as the page shows it, line by line, records its five frames (its first line was a
-- `local`, gone by the next line: each console line is a chunk of its own).
local sn = require "shadenet"

local t0 = sn.clock()
dofile("examples/live_edit.lua")
print(("example ran in %.1f s"):format(sn.clock() - t0))
for _, mode in ipairs({ "network", "truth", "error", "side" }) do
  local img = sn.image.load("out/live_edit/" .. mode .. ".png")
  assert(img:size() == 480, mode .. " view saved at 480 pixels wide")
end

local net = sn.keep("toon 8x12", error)  -- kept: error() would be called only if it were not
local truth = sn.live.render { mode = "truth", width = 160, height = 160 }:read()
local trained = sn.live.render { mode = "network", width = 160, height = 160 }:read()
local mse = sn.image.mse(trained, truth, { channels = 3, mask = truth })
print(("network vs truth, image MSE over covered pixels: %.4g (val MSE %.4g)"):format(mse, net:best().val_mse))
assert(mse < 0.01, "the trained network looks like the toon shading")

local source = assert(io.open("examples/live_edit.lua")):read("*a")
local params = net:params()
local edits = 0
for line in source:gmatch("\n%-%- (L%[[^\n]-)%s+%-%-[^\n]*") do
  local chunk = assert(loadstring(line, "edit"))
  setfenv(chunk, { L = net.layers })
  chunk()
  local edited = sn.live.render { mode = "network", width = 160, height = 160 }:read()
  local change = sn.image.mse(edited, trained, { channels = 3, mask = truth })
  print(("%-40s changes the picture by MSE %.4g"):format(line, change))
  assert(change > 1e-3, "the edit '" .. line .. "' is visible")
  net:set_params(params)
  edits = edits + 1
end
assert(edits == 3, "three edits in the example, found " .. edits)
assert(sn.image.mse(sn.live.render { mode = "network", width = 160, height = 160 }:read(), trained) == 0,
       "the network is back to its trained weights")

print("edits checked; the sweep of docs/live-mode.md section 6 at the console:")

package.path = "tests/live/?.lua;" .. package.path
local H = require "harness"
local page = H.read("docs/live-mode.md")
local section = page:match("\n## 6%.(.-)\n## ")
local block = section and section:match("```lua\n(.-)\n```")
assert(block, "docs/live-mode.md section 6 has its lua block")
local dir = block:match('dir = "([^"]+)"')
assert(dir, "the sweep names its folder")
os.execute(("rm -rf %q"):format(dir))
local s = H.start { dir = "out/live_tests/example_sweep", script = "examples/live_edit.lua", window = false, limit = 240 }
s:wait_log("%[live%] ran ", 200)
for line in (block .. "\n"):gmatch("([^\n]*)\n") do s:send(line) end
local last = ("%s/frame-%04d.png"):format(dir, 5)
for _ = 1, 1200 do
  if H.exists(last) then break end
  H.sleep(0.05)
end
assert(H.exists(last), "the console's sweep wrote its five frames:\n" .. s:log())
assert(not s:log():find("stdin:", 1, true), "the lines ran without an error:\n" .. s:log())
local a, b = sn.image.load(dir .. "/frame-0001.png"), sn.image.load(last)
assert(sn.image.mse(a, b) > 1e-4, "the swept weight changes the picture")
s:stop()
print(("the sweep typed at the console wrote %s/frame-0001..5.png"):format(dir))

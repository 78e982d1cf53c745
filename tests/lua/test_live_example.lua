-- examples/live_edit.lua does what docs/live-mode.md says: run plainly it trains the toon
-- network once and saves its four views; the network is close to the truth; each edit line of
-- its edit block (commented out) is valid Lua that changes the picture, and the kept network
-- comes back untouched.
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

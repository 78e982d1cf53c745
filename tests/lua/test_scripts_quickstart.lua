-- examples/quickstart.lua, the README's main job: it writes its figure and table, says where,
-- and its networks shade like the models on the mesh they learned from.
local C = require "script_check"
local sn = require "shadenet"

local dir = C.tmpdir("quickstart")
local t0 = sn.clock()
local out = C.ok("examples/quickstart.lua", { dir })
local seconds = sn.clock() - t0
assert(seconds < 180, "the quickstart takes under 3 minutes, took " .. seconds)
assert(out:find("wrote " .. dir .. "/quickstart.png and " .. dir .. "/table.md", 1, true), "it prints where it wrote:\n" .. out)
local img = sn.image.load(dir .. "/quickstart.png")
local w, h = img:size()
assert(w > 600 and h > 800, "a 4-row figure")
local md = C.read(dir .. "/table.md")
local n = 0
for name, val, train, test in md:gmatch("| (%a+) | mlp[^|]+| (%S+) | (%S+) | (%S+) |") do
  n = n + 1
  val, train, test = tonumber(val), tonumber(train), tonumber(test)
  assert(C.finite(val) and val < 1e-3, name .. ": validation MSE " .. tostring(val))
  assert(C.finite(train) and train < 2e-3, name .. ": image MSE on the training mesh " .. tostring(train))
  assert(C.finite(test) and test < 0.2, name .. ": image MSE on the test mesh " .. tostring(test))
end
assert(n == 2, "Phong and GGX rows in the table:\n" .. md)
C.rm(dir)
print("quickstart: ok")

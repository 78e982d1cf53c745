-- A failed GL allocation leaves nothing behind (issue 13): a render target too large for the
-- device is an error naming its size, and the next small buffer and target still work (the GL
-- error flag it raised used to make the next 16-byte buffer fail "out of GPU memory").
local sn = require "shadenet"

local ok, err = pcall(sn.target, { width = 16384, height = 16384, colors = 8 })  -- 34 GB of RGBA32F
if ok then
  print("note: this device holds a 16384 x 16384 x 8 RGBA32F target; the failure path is not exercised")
else
  assert(tostring(err):find("16384x16384 render target", 1, true), tostring(err))
end
local b = sn.buffer { type = "float", size = 4 }
b:set(1, 2.5)
assert(b:get(1) == 2.5, "a small buffer after the failure")
local t = sn.target { width = 8, height = 8 }
t:clear({ 0.25, 0.5, 0.75, 1 })
assert(math.abs(t:read():get(4, 4)[2] - 0.5) < 1e-6, "a small target after the failure")
print("ok")

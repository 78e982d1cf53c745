-- A buf:ffi() pointer keeps its buffer alive (issue 13): the buffer used to be collected under
-- it, and the pointer then read zeros from freed storage.
local sn = require "shadenet"

local p = (function()
  local b = sn.buffer { type = "float", size = 1024 }
  for i = 1, 1024 do b:set(i, i * 0.5) end
  return b:ffi()
end)()
for _ = 1, 4 do collectgarbage() end
local tmp = {}
for i = 1, 200 do tmp[i] = sn.buffer { type = "float", size = 1024 } end  -- reuse freed storage, if any
for i = 1, 1024 do assert(p[i - 1] == i * 0.5, "element " .. i .. " reads " .. p[i - 1]) end
print("ok")

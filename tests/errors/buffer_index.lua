-- expect: buffer_index\.lua:5: buffer index 9 out of range 1\.\.8
local sn = require "shadenet"

local b = sn.buffer { size = 8 }
print(b:get(9))

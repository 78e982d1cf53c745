-- expect: use_after_release\.lua:6: this Buffer was released; it can no longer be used
local sn = require "shadenet"

local b = sn.buffer { size = 8 }
b:release()
b:fill(1)

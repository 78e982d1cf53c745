-- expect: wrong_argument_type\.lua:5: buffer index: number expected, got string
local sn = require "shadenet"

local b = sn.buffer { size = 8 }
b:set("first", 1)

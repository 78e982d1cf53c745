-- expect: dispatch_groups\.lua:6: program:dispatch option 'groups': x must be a whole number in 1\.\.[0-9]+ \(this driver's limit\), got 0
local sn = require "shadenet"

local b = sn.buffer { size = 8 }
local p = sn.program { compute = "examples/square.comp", defines = { LOCAL_SIZE = 8 } }
p:dispatch { groups = 0, buffers = { b }, uniforms = { u_count = 8 } }

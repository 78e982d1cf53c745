-- expect: dispatch_groups\.lua:6: workgroup count 0x1x1 is outside
local sn = require "shadenet"

local b = sn.buffer { size = 8 }
local p = sn.program { compute = "examples/square.comp", defines = { LOCAL_SIZE = 8 } }
p:dispatch { groups = 0, buffers = { b }, uniforms = { u_count = 8 } }

-- expect: unknown_uniform\.lua:6: program examples/square\.comp has no uniform 'u_size' \(valid: u_count\)
local sn = require "shadenet"

local b = sn.buffer { size = 8 }
local p = sn.program { compute = "examples/square.comp", defines = { LOCAL_SIZE = 8 } }
p:dispatch { groups = 1, buffers = { b }, uniforms = { u_size = 8 } }

-- expect: dispatch_block_unbound\.lua:8: program:dispatch option 'buffers': tests/data/shaders/poly\.comp's buffer block 'Out' \(binding 1\) has no buffer: give it one, as buffers\[2\] or buffers\.Out
-- A block left out read whatever an earlier dispatch had bound there.
local sn = require "shadenet"
local xs, ys = sn.buffer { size = 8 }, sn.buffer { size = 8 }
local p = sn.program { compute = "tests/data/shaders/poly.comp", defines = { LOCAL_SIZE = 8 } }
p:dispatch { groups = 1, buffers = { xs, ys }, uniforms = { u_count = 8, u_scale = 1 } }
-- Out stays bound to ys from the call before; this call forgets it.
p:dispatch { groups = 1, buffers = { xs }, uniforms = { u_count = 8, u_scale = 1 } }

-- expect: dispatch_shared_binding\.lua:8: program:dispatch option 'buffers': tests/data/shaders/shared_binding\.comp: buffer blocks 'In' and 'Out' share binding 0 \(a block without layout\(binding = N\) gets 0\); give each block its own binding
local sn = require "shadenet"

-- Both blocks used to get buffer `b` (the last bound to binding 0): the shader read its own
-- output and overwrote the read-only input.
local prog = sn.program { compute = "tests/data/shaders/shared_binding.comp" }
local a, b = sn.buffer { size = 4 }, sn.buffer { size = 4 }
prog:dispatch { groups = 4, buffers = { In = a, Out = b } }

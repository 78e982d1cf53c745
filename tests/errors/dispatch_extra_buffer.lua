-- expect: dispatch_extra_buffer\.lua:6: program:dispatch option 'buffers': buffer 3 binds binding 2, where tests/data/shaders/poly\.comp has no buffer block \(its blocks and bindings: In at 0, Out at 1\)
-- An extra buffer was dropped without a word.
local sn = require "shadenet"
local xs, ys = sn.buffer { size = 8 }, sn.buffer { size = 8 }
local p = sn.program { compute = "tests/data/shaders/poly.comp", defines = { LOCAL_SIZE = 8 } }
p:dispatch { groups = 1, buffers = { xs, ys, xs }, uniforms = { u_count = 8, u_scale = 1 } }

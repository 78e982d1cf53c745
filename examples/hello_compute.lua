-- Squares a buffer of numbers in a compute shader and prints the result.
--   build/shadenet examples/hello_compute.lua
local sn = require "shadenet"

local values = sn.buffer { type = "float32", data = { 1, 2, 3, 4, 5, 6, 7, 8 } }
local square = sn.program { compute = "examples/square.comp", defines = { LOCAL_SIZE = 64 } }

-- one invocation per element; the shader skips indices past the end
square:dispatch { groups = math.ceil(values:size() / 64), buffers = { values },
                  uniforms = { u_count = values:size() } }

print("squared: " .. table.concat(values:download(), " "))

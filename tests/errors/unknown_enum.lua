-- expect: unknown_enum\.lua:4: unknown buffer type 'float16' \(valid: float32, uint32, int32, vec2, vec4, uvec4, ivec4\)
local sn = require "shadenet"

sn.buffer { type = "float16", size = 4 }

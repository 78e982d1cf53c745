-- expect: tests/errors/unknown_option_key\.lua:4: sn\.buffer: unknown option 'typ' \(valid: type, size, data, fill\)
local sn = require "shadenet"

sn.buffer { typ = "float32", size = 4 }

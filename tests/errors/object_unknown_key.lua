-- expect: object_unknown_key\.lua:6: Buffer has no field 1 \(it has: download, ffi, fill, get, pointer, release, set, size, type, upload\)
-- Nothing near: the error lists what the type has (here buf[1] for buf:get(1)).
local sn = require "shadenet"

local buf = sn.buffer { size = 4 }
print(buf[1])

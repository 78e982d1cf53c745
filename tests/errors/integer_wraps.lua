-- expect: integer_wraps\.lua:5: sn\.mesh\.sphere option 'segments': integer within \+-\(2\^31 - 1\) expected, got 4294967304
local sn = require "shadenet"

-- 2^32 + 8 used to wrap to 8: a sphere of 8 segments, and no word.
sn.mesh.sphere { segments = 2 ^ 32 + 8 }

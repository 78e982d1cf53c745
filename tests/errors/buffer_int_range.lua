-- expect: buffer_int_range\.lua:4: sn\.buffer option .data. element 2: 3e\+09 is not an integer in \[-2147483648, 2147483647\], the range of int32
local sn = require "shadenet"
-- 3e9 wrapped to -2147483648 without a word.
sn.buffer { type = "int32", data = { 1, 3e9 } }

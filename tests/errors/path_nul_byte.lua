-- expect: path_nul_byte\.lua:7: net:save path: the string holds a NUL byte \(\\0\)
-- then-missing: out/nul_test/a
local sn = require "shadenet"

-- A NUL byte must not cut the path short (it used to write out/nul_test/a).
local net = sn.mlp { inputs = 6, hidden = { 4 } }
net:save("out/nul_test/a\0b.snmlp")

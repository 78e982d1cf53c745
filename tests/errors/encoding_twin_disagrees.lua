-- expect: encoding_twin_disagrees\.lua:5: sn\.encoding\.define: encoding 'halved': its GLSL gives .* as output 2 of {.*} \(an input of 1 component\), its Lua twin
local sn = require "shadenet"
-- The GLSL and its Lua twin must agree (within 1e-4) before the name can be used: here output 2
-- is x / 2 in GLSL and x / 3 in Lua.
sn.encoding.define { name = "halved", outputs = function(w) return 2 * w end,
                     glsl = "int c = j / 2; return (j & 1) == 0 ? x[c] : 0.5 * x[c];",
                     lua = function(x) local o = {} for c = 1, #x do o[#o + 1] = x[c]; o[#o + 1] = x[c] / 3 end return o end }

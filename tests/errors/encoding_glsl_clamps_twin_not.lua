-- expect: encoding_glsl_clamps_twin_not\.lua:7: sn\.encoding\.define: encoding 'sq': its GLSL gives 1 as output 1 of {1\.19583} \(an input of 1 component\), its Lua twin 1\.43
-- A GLSL that clamps its input to [-1, 1] and a twin that does not agree on [-1, 1] alone: they
-- were compared there only, and a position of 2.5 then trained 6.25 on the cpu backend (the twin)
-- and 1 on gl. The check goes on to inputs of +-300; outside [-1, 1] the first sample input is
-- 1.19583.
local sn = require "shadenet"
sn.encoding.define { name = "sq", outputs = function(w) return w end,
                     glsl = "float y = clamp(x[j], -1.0, 1.0); return y * y;",
                     lua = function(x) local o = {} for i = 1, #x do o[i] = x[i] * x[i] end return o end }

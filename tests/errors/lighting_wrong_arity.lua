-- expect: lighting_wrong_arity\.lua:4: sn\.lighting\.ggx parameter 'f0': 3 numbers \{r, g, b\} or 1 number expected, got 2
local sn = require "shadenet"

local truth = sn.lighting.ggx { f0 = { 1.0, 0.71 } }

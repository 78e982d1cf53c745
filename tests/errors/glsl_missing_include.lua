-- expect: tests/data/shaders/missing_include\.comp:2: cannot find #include "no_such_file\.glsl"
local sn = require "shadenet"
sn.program { compute = "tests/data/shaders/missing_include.comp" }

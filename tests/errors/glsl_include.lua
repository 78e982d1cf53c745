-- expect: tests/data/shaders/broken_helper\.glsl:5: .*undeclared_thing
-- expect:     return undeclared_thing \* 2\.0;
-- expect: tests/errors/glsl_include\.lua:7:
-- A GLSL error inside an #include is reported in the included file, with its line printed.
local sn = require "shadenet"

sn.program { compute = "tests/data/shaders/uses_broken.comp" }

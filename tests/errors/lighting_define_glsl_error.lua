-- expect: lighting_define_glsl_error\.lua:6: GLSL compile error in shaders/eval_lighting\.comp:
-- expect: tests/data/broken_lighting\.glsl:4: error: .brightness' undeclared
local sn = require "shadenet"

-- The GLSL file has an undefined name on its line 4: the error names that file and line.
sn.lighting.define { name = "broken", glsl = "tests/data/broken_lighting.glsl", twin = function() return { 0, 0, 0 } end }

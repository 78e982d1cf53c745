-- expect: lighting_define_include_missing\.lua:6 \(glsl of helped\):1: cannot find #include "nowhere_helper\.glsl" \(looked in tests/errors/, shaders/include/ and shaders/\)
-- GLSL given as a string looks for its #includes beside the defining script (it looked in
-- shaders/ alone, and said it had looked "beside the file").
local sn = require "shadenet"

sn.lighting.define { name = "helped", twin = function() return { 0, 0, 0 } end,
                     glsl = '#include "nowhere_helper.glsl"\nvec3 shade(Surface s, Params p) { return vec3(0.0); }' }

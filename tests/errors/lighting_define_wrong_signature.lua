-- expect: lighting_define_wrong_signature\.lua:4: lighting model 'lambert': its glsl \(tests/errors/lighting_define_wrong_signature\.lua:4 \(glsl of lambert\)\) must define vec3 shade\(Surface s, Params p\)
local sn = require "shadenet"

sn.lighting.define { name = "lambert", glsl = "vec3 shade(vec3 n, vec3 v) { return n; }",
                     twin = function() return { 0, 0, 0 } end }

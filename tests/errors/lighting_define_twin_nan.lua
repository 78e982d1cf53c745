-- expect: lighting_define_twin_nan\.lua:4: sn\.lighting\.define 'lambert': its twin returned \{-?nan, 0, 0\} at normal \{0, 1, 0\}, view \{0\.6, 0\.8, 0\}: it must be finite
local sn = require "shadenet"

sn.lighting.define { name = "lambert", glsl = "vec3 shade(Surface s, Params p) { return vec3(0.0); }",
                     twin = function(s, p) return { 0 / 0, 0, 0 } end }

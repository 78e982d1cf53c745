-- expect: lighting_define_twin_shape\.lua:4: lighting model 'lambert': its twin must return \{r, g, b\} \(3 numbers\), got number
local sn = require "shadenet"

sn.lighting.define { name = "lambert", glsl = "vec3 shade(Surface s, Params p) { return vec3(0.0); }",
                     twin = function(s, p) return 0.5 end }

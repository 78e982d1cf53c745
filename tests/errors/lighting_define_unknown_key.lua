-- expect: lighting_define_unknown_key\.lua:4: sn\.lighting\.define: unknown option 'parms' \(valid: name, params, glsl, attributes, twin, bound\)
local sn = require "shadenet"

sn.lighting.define { name = "lambert", glsl = "vec3 shade(Surface s, Params p) { return vec3(0.0); }",
                     twin = function() return { 0, 0, 0 } end, parms = {} }

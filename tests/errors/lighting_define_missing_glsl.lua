-- expect: lighting_define_missing_glsl\.lua:4: sn\.lighting\.define 'lambert': 'glsl' is required: a \.glsl file or source text defining vec3 shade\(Surface s, Params p\)
local sn = require "shadenet"

sn.lighting.define { name = "lambert", twin = function() return { 0, 0, 0 } end }

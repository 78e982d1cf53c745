-- expect: lighting_define_shadows_builtin\.lua:4: lighting model 'ggx' would shadow the built-in model of that name; choose another name
local sn = require "shadenet"

sn.lighting.define { name = "ggx", glsl = "vec3 shade(Surface s, Params p) { return vec3(0.0); }",
                     twin = function() return { 0, 0, 0 } end }

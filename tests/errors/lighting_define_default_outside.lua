-- expect: lighting_define_default_outside\.lua:4: lighting model 'lambert' parameter 'albedo': the default 1\.5 lies outside its range \[0, 1\]
local sn = require "shadenet"

sn.lighting.define { name = "lambert", params = { albedo = { default = 1.5, range = { 0, 1 } } },
                     glsl = "vec3 shade(Surface s, Params p) { return vec3(p.albedo); }",
                     twin = function(s, p) return { p.albedo, p.albedo, p.albedo } end }

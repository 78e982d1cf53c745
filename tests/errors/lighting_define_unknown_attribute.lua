-- expect: lighting_define_unknown_attribute\.lua:4: lighting model 'lambert': unknown attribute 'curvature' \(valid: base_color, uv, position, world_position, tangent, bitangent; normal and view are always given\)
local sn = require "shadenet"

sn.lighting.define { name = "lambert", attributes = { "curvature" },
                     glsl = "vec3 shade(Surface s, Params p) { return vec3(0.0); }",
                     twin = function() return { 0, 0, 0 } end }

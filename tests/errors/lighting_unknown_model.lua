-- expect: lighting_unknown_model\.lua:4: unknown lighting model 'sn\.lighting\.gxx' \(valid: phong, blinn_phong, ggx, toon3, textured_phong
local sn = require "shadenet"

local truth = sn.lighting.gxx { roughness = 0.3 }

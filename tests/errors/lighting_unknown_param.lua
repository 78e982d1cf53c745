-- expect: lighting_unknown_param\.lua:4: sn\.lighting\.ggx: unknown parameter 'rougness' \(valid: roughness, f0, diffuse, ambient\)
local sn = require "shadenet"

local truth = sn.lighting.ggx { rougness = 0.3 }

-- expect: lighting_negative_roughness\.lua:4: sn\.lighting\.ggx parameter 'roughness' \(perceptual roughness
-- expect: must lie in \[0, 1\], got -0\.1
local sn = require "shadenet"
local truth = sn.lighting.ggx { roughness = -0.1 }

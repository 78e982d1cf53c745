-- expect: lighting_negative_color\.lua:4: sn\.lighting\.phong parameter 'color' \(C_p, the diffuse reflection coefficient
-- expect: must lie in \[0, 1000\], got \{0\.5, -0\.2, 0\.1\}
local sn = require "shadenet"
local truth = sn.lighting.phong { color = { 0.5, -0.2, 0.1 } }

-- expect: lighting_thresholds_order\.lua:4: sn\.lighting\.toon3 parameter 'thresholds' must be in order t1 <= t2 <= t3 <= t4, got \{0\.5, 0\.3, 0\.6, 0\.9\}
local sn = require "shadenet"

local truth = sn.lighting.toon3 { thresholds = { 0.5, 0.3, 0.6, 0.9 } }

-- expect: image_bad_extension\.lua:6: cannot save 'out/errors/never_written\.xyz': unknown image extension '\.xyz'
-- then-missing: out/errors/never_written.xyz
local sn = require "shadenet"

local img = sn.image.new { width = 4, height = 4 }
img:save("out/errors/never_written.xyz")

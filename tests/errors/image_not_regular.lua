-- expect: image_not_regular\.lua:5: image file '/dev/zero' is not a regular file
local sn = require "shadenet"

-- /dev/zero used to be read until memory ran out.
sn.image.load("/dev/zero")

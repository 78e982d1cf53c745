-- expect: program_not_regular\.lua:5: cannot read shader file '/dev/zero': not a regular file
local sn = require "shadenet"

-- /dev/zero used to be read until memory ran out.
sn.program { compute = "/dev/zero" }

-- expect: integer_beyond_2_53\.lua:5: sn\.mlp option 'inputs': integer within -2\^53\.\.2\^53 expected, got inf
local sn = require "shadenet"

-- An infinite count is an error, never a cast with undefined behaviour.
sn.mlp { inputs = math.huge, hidden = { 4 } }

-- expect: mlp_forward_overflow\.lua:5: net:forward sample 2 input 3 is 1e\+39, beyond float's range \(3\.4e38\): values must be finite floats
local sn = require "shadenet"
local net = sn.mlp { inputs = 3, hidden = { 2 }, outputs = 1 }
-- As a double 1e39 is finite; as the float the network runs in, it is infinite.
net:forward { { 1, 2, 3 }, { 0, 0, 1e39 } }

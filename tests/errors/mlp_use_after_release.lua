-- expect: mlp_use_after_release\.lua:5: this Mlp was released; it can no longer be used
local sn = require "shadenet"
local net = sn.mlp { inputs = 6, hidden = {8} }
net:release()
print(net:version())

-- expect: encoding_oneblob_no_range\.lua:3: sn\.mlp option 'encoding': encoding 'oneblob' of input 'position': 'position' has no fixed range; give it as range = \{min, max\}
local sn = require "shadenet"
sn.mlp { inputs = { "position", "view" }, hidden = { 8 }, encoding = { position = { "oneblob", bins = 8 } } }

-- expect: encoding_bins_range\.lua:3: sn\.mlp option 'encoding': encoding 'oneblob' of input 'uv': bins must be 2\.\.64, got 1
local sn = require "shadenet"
sn.mlp { inputs = { "normal", "uv" }, hidden = { 8 }, encoding = { uv = { "oneblob", bins = 1 } } }

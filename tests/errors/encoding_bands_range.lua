-- expect: encoding_bands_range\.lua:3: sn\.mlp option 'encoding': encoding 'frequency' of input 'uv': bands must be 1\.\.16, got 20
local sn = require "shadenet"
sn.mlp { inputs = { "normal", "uv" }, hidden = { 8 }, encoding = { uv = { "frequency", bands = 20 } } }

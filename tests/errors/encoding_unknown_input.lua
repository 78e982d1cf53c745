-- expect: encoding_unknown_input\.lua:3: sn\.mlp option 'encoding': the network has no input 'uv' \(its inputs: normal, view\)
local sn = require "shadenet"
sn.mlp { inputs = { "normal", "view" }, hidden = { 8 }, encoding = { uv = { "frequency", bands = 8 } } }

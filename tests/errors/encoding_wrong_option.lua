-- expect: encoding_wrong_option\.lua:3: sn\.mlp option 'encoding' of input 'normal': 'sh' takes degree, not 'bands'
local sn = require "shadenet"
sn.mlp { inputs = { "normal", "uv" }, hidden = { 8 }, encoding = { normal = { "sh", bands = 3 } } }

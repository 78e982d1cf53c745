-- expect: encoding_unknown\.lua:3: sn\.mlp option 'encoding' of input 'uv': unknown encoding 'fourier' \(valid: identity, frequency, oneblob, sh, triangle_wave\)
local sn = require "shadenet"
sn.mlp { inputs = { "normal", "uv" }, hidden = { 8 }, encoding = { uv = { "fourier", bands = 4 } } }

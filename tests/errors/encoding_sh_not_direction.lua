-- expect: encoding_sh_not_direction\.lua:3: sn\.mlp option 'encoding': encoding 'sh' of input 'uv': needs an input of 3 components \(a direction such as normal or view\), 'uv' has 2
local sn = require "shadenet"
sn.mlp { inputs = { "normal", "uv" }, hidden = { 8 }, encoding = { uv = "sh" } }

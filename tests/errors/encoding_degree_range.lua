-- expect: encoding_degree_range\.lua:3: sn\.mlp option 'encoding': encoding 'sh' of input 'normal': degree must be 1\.\.4, got 5
local sn = require "shadenet"
sn.mlp { inputs = { "normal", "view" }, hidden = { 8 }, encoding = { normal = { "sh", degree = 5 } } }

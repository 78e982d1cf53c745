-- expect: encoding_unnamed_inputs\.lua:3: sn\.mlp option 'encoding': encodings are given per named input, and this network's inputs have no names; name them, e\.g\. inputs = \{ "normal", "view", "uv" \}
local sn = require "shadenet"
sn.mlp { inputs = 8, hidden = { 8 }, encoding = { uv = { "frequency", bands = 8 } } }

-- expect: encoding_too_wide\.lua:3: sn\.mlp: the encoded inputs are 384 wide, at most 256 \(fewer bands, bins or a lower degree\)
local sn = require "shadenet"
sn.mlp { inputs = { "normal", "view" }, hidden = { 8 }, encoding = { normal = { "oneblob", bins = 64 }, view = { "oneblob", bins = 64 } } }

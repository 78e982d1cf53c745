-- expect: object_unknown_field\.lua:6: Mlp has no field 'layer' \(did you mean layers\?\)
-- A misspelt field of an object is an error where it is read, not a nil passed on.
local sn = require "shadenet"

local net = sn.mlp { inputs = 3, outputs = 3, hidden = { 8 } }
local first = net.layer[1]

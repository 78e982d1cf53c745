-- expect: sn_unknown_name\.lua:8: sn\.mse is not part of shadenet \(did you mean sn\.image\.mse\?\)
-- A name shadenet does not have fails where it is read, with the names near it (a typo, or a
-- function of a sub-table); rawget tests for one without the error.
local sn = require "shadenet"

assert(rawget(sn, "mse") == nil)
assert(not pcall(function() return sn.tain end) and select(2, pcall(function() return sn.tain end)):find("did you mean sn.train?", 1, true))
local mse = sn.mse

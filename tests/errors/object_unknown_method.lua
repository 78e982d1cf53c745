-- expect: object_unknown_method\.lua:6: Camera has no field 'aspekt' \(did you mean aspect\?\)
-- A misspelt method of a type whose methods are a table: the same error, with its near names.
local sn = require "shadenet"

local cam = sn.camera {}
print(cam:aspekt())

-- expect: tests/errors/lua_runtime\.lua:6: attempt to call field 'not_a_function'
-- expect: stack traceback
local sn = require "shadenet"

local function inner()
  sn.not_a_function()
end
inner()

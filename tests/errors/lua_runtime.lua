-- expect: tests/errors/lua_runtime\.lua:7: attempt to call local 'not_a_function'
-- expect: stack traceback
local sn = require "shadenet"

local function inner()
  local not_a_function
  not_a_function()
end
inner()

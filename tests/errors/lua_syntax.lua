-- expect: tests/errors/lua_syntax\.lua:6: .*near
-- A script with a syntax error names its file and line and exits non-zero.
local sn = require "shadenet"

local x = 1
local y = = 2

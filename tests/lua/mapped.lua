-- mapped(pattern): whether a file whose path matches the Lua pattern is mapped into this process
-- (/proc/self/maps), for tests that a library is loaded only when it is needed.
return function(pattern)
  local f = assert(io.open("/proc/self/maps"))
  local maps = f:read("*a")
  f:close()
  return maps:find(pattern) ~= nil
end

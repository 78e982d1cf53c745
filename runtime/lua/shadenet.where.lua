-- Errors of the runtime's own Lua files, at the script's line. A C function these files call
-- (an object's method, sn.camera, image:save) prefixes its error with the runtime line that
-- called it ("runtime/lua/shadenet.scene.lua:37: "), which tells a script nothing: the runtime
-- catches it and raises the message again, without that prefix, at the script's line.
local where = {}

-- The error's message without a leading position in one of the runtime's files.
function where.message(err)
  return (tostring(err):gsub("^runtime/%a+/shadenet[%w._]*%.lua:%d+: ", "", 1))
end

return where

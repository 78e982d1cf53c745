-- Option tables of scripts/lib are strict, as every C++ entry point of shadenet is: a key the
-- function does not take is an error naming it, what is near it and the valid keys, and a
-- missing required key is an error naming it. The error names the line of the script that
-- called into scripts/lib (the first caller outside this folder), not a line of the library:
--   my_script.lua:12: exp.run: unknown option 'epoch' (valid: id, hidden, ...; did you mean epochs?)
--   my_script.lua:12: exp.run option 'data' is required (a dataset description: E:data_desc{...})
local sn = require "shadenet"

local options = {}

-- This folder, as the chunks loaded from it name their source ("@scripts/lib/" or an absolute
-- path): frames whose source starts with it are the library's.
local lib_source = "@" .. (debug.getinfo(1, "S").source:match("^@(.*/)[^/]*$") or "")

-- error(message) at the first Lua frame outside scripts/lib: the user's line. C frames (pcall)
-- are passed over; without any such frame the message goes without a position.
function options.error(message)
  local level = 2
  while true do
    local info = debug.getinfo(level, "S")
    if not info then error(message, 0) end
    -- (error is not tail-called: that would drop this frame and shift the level by one)
    if info.what ~= "C" and info.source:sub(1, #lib_source) ~= lib_source then error(message, level) end
    level = level + 1
  end
end

-- options.check(o, what, valid [, required [, hints]]) -> o
-- `o` is the options table of the function `what` ("exp.run"); `valid` lists the keys it takes
-- (in the order the message lists them), `required` those it cannot go without; hints[key] is
-- a few words after "is required" (what the key holds).
function options.check(o, what, valid, required, hints)
  if type(o) ~= "table" then options.error(string.format("%s: options table expected, got %s", what, type(o))) end
  local known = {}
  for _, k in ipairs(valid) do known[k] = true end
  for k in pairs(o) do
    if type(k) ~= "string" then
      options.error(string.format("%s: options must be named (key = value), got the key %s", what, tostring(k)))
    end
    if not known[k] then
      local near = sn.near(k, valid)
      options.error(string.format("%s: unknown option '%s' (valid: %s%s)", what, k, table.concat(valid, ", "),
                                  #near > 0 and "; did you mean " .. table.concat(near, ", ") .. "?" or ""))
    end
  end
  for _, k in ipairs(required or {}) do
    if o[k] == nil then
      options.error(string.format("%s option '%s' is required%s", what, k,
                                  hints and hints[k] and " (" .. hints[k] .. ")" or ""))
    end
  end
  return o
end

-- options.check_list(list, what, valid [, required]): options.check on every entry of a list
-- of option tables (R:table's columns, plot.lines' series), each named what[i].
function options.check_list(list, what, valid, required)
  if list == nil then return list end
  if type(list) ~= "table" then options.error(string.format("%s: a list expected, got %s", what, type(list))) end
  for i, o in ipairs(list) do options.check(o, string.format("%s[%d]", what, i), valid, required) end
  return list
end

return options

-- The Lua side of `require "shadenet"`: the C++ core plus conveniences written in Lua.
local core = require "shadenet.core"
local ffi = require "ffi"

local sn = core

-- buf:ffi([ctype]) -> a cdata pointer (float* by default) onto the buffer's storage, for fast
-- per-element loops in LuaJIT. The pointer keeps its buffer alive (its finalizer holds it), so
-- the collector cannot free the storage under it; buf:release() still ends it. After a dispatch
-- call sn.finish() before reading through it.
-- Its errors (a released buffer, a ctype that is no pointer) name the script's line, not this file's.
local Buffer = debug.getregistry().Buffer.__index
function Buffer.ffi(buf, ctype)
  local ok, kind = pcall(Buffer.type, buf)  -- a C function under pcall: its message has no position
  if not ok then error("buf:ffi: " .. tostring(kind), 2) end
  ctype = ctype or ((kind == "uint32" or kind == "uvec4") and "uint32_t*"
                    or (kind == "int32" or kind == "ivec4") and "int32_t*" or "float*")
  local cast
  ok, cast = pcall(ffi.cast, ctype, Buffer.pointer(buf))
  if not ok then
    error(("buf:ffi: ctype %s: %s (a pointer type expected, such as \"float*\")"):format(
      type(ctype) == "string" and "'" .. ctype .. "'" or tostring(ctype), tostring(cast):gsub("^[^\n]-:%d+: ", "")), 2)
  end
  return ffi.gc(cast, function() return buf end)
end

-- os.exit(code) closes the Lua state first, as the end of a script does, so finalizers run and
-- sn.fs.tempdir folders go (an interrupted sweep's os.exit(130) left them in $TMPDIR);
-- os.exit(code, false) exits at once.
local exit = os.exit
os.exit = function(code, close)
  if close == nil then close = true end
  return exit(code, close)
end

require "shadenet.live"  -- sn.keep, sn.live.*, sn.record
require "shadenet.scene"  -- scene:render
require "shadenet.vec3"  -- sn.vec3 (for lighting twins)

-- Reading a name shadenet does not have (sn.tain, or sn.mse for sn.image.mse) is an error naming
-- it and what is near, where the script reads it, instead of "attempt to call a nil value" (or a
-- nil passed on). rawget(sn, name) tests for a name without the error.
-- Edits between two short names: insertions, deletions, substitutions and swaps of two
-- neighbours ("sampels" is one edit from "samples"; Damerau-Levenshtein, optimal alignment).
local function distance(a, b)
  local before, prev = nil, {}
  for j = 0, #b do prev[j] = j end
  for i = 1, #a do
    local cur = { [0] = i }
    for j = 1, #b do
      cur[j] = math.min(prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a:byte(i) == b:byte(j) and 0 or 1))
      if before and j > 1 and a:byte(i) == b:byte(j - 1) and a:byte(i - 1) == b:byte(j) then
        cur[j] = math.min(cur[j], before[j - 2] + 1)
      end
    end
    before, prev = prev, cur
  end
  return prev[#b]
end
-- sn.near(name, names) -> the names of the list `names` near `name` (a typo of one of them:
-- at most one edit in four characters), sorted; for "did you mean" in scripts' own errors.
function sn.near(name, names)
  if type(name) ~= "string" then error("sn.near: argument 1 (the name): string expected, got " .. type(name), 2) end
  if type(names) ~= "table" then
    error("sn.near: argument 2 (the names): a list of strings expected, got " .. type(names), 2)
  end
  for i, k in ipairs(names) do
    if type(k) ~= "string" then
      error(("sn.near: argument 2 (the names): element %d is a %s, not a string"):format(i, type(k)), 2)
    end
  end
  local out = {}
  for _, k in ipairs(names) do
    if distance(k, name) <= math.max(1, math.floor(#name / 4)) then out[#out + 1] = k end
  end
  table.sort(out)
  return out
end

-- Reading a field an object does not have (net.layer for net.layers, cam:fovv()) is an error
-- naming the type, the field and what it has, where the script reads it: it used to read nil.
-- registry["shadenet.unknown_field"](type, key, names) is the message (the Mlp's own __index,
-- in C++, raises it too).
local function unknown_field(type_name, key, names)
  local list = {}
  for k in pairs(names) do if type(k) == "string" and not k:match("^__") then list[#list + 1] = k end end
  table.sort(list)
  local near = type(key) == "string" and sn.near(key, list) or {}
  return type_name .. " has no field " .. (type(key) == "string" and "'" .. key .. "'" or tostring(key)) ..
         (#near > 0 and " (did you mean " .. table.concat(near, ", ") .. "?)" or " (it has: " .. table.concat(list, ", ") .. ")")
end
debug.getregistry()["shadenet.unknown_field"] = unknown_field
for name, mt in pairs(debug.getregistry()) do
  local methods = type(mt) == "table" and rawget(mt, "__name") == name and
                  (type(rawget(mt, "__index")) == "table" and rawget(mt, "__index") or rawget(mt, "__methods"))
  if methods then
    setmetatable(methods, { __index = function(t, key) error(unknown_field(name, key, t), 2) end })
  end
end

-- The message for `path`.name missing from the table t (sn itself, or one of its tables): the
-- names of t near it, and the name where the module has it elsewhere (sn.mse: sn.image.mse).
local function not_part(path, t, name)
  local names, near = {}, {}
  for k in pairs(t) do if type(k) == "string" then names[#names + 1] = k end end
  for _, k in ipairs(sn.near(name, names)) do near[#near + 1] = path .. "." .. k end
  if t ~= sn and rawget(sn, name) ~= nil then near[#near + 1] = "sn." .. name end
  for k, v in pairs(sn) do
    if type(k) == "string" and type(v) == "table" and v ~= t and rawget(v, name) ~= nil then
      near[#near + 1] = "sn." .. k .. "." .. name
    end
  end
  table.sort(near)
  return path .. "." .. name .. " is not part of shadenet" ..
         (#near > 0 and " (did you mean " .. table.concat(near, ", ") .. "?)" or " (the API: docs/lua-api.md)")
end
local function strict_index(path)
  return function(t, name)
    if type(name) ~= "string" then return nil end
    error(not_part(path, t, name), 2)
  end
end

setmetatable(sn, { __index = strict_index("sn") })
-- sn's tables too (sn.image.mes, sn.mesh.shpere{} read nil): those without a metatable get one;
-- a callable one (__call) gets the __index; one with its own __index (sn.lighting: the models
-- by name) keeps it. Fields added later are read as usual; rawget still probes quietly.
for k, v in pairs(sn) do
  if type(k) == "string" and type(v) == "table" then
    local mt = getmetatable(v)
    if mt == nil then setmetatable(v, { __index = strict_index("sn." .. k) })
    elseif type(mt) == "table" and rawget(mt, "__index") == nil then mt.__index = strict_index("sn." .. k) end
  end
end

return sn

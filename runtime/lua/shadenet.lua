-- The Lua side of `require "shadenet"`: the C++ core plus conveniences written in Lua.
local core = require "shadenet.core"
local ffi = require "ffi"

local sn = core

-- buf:ffi([ctype]) -> a cdata pointer (float* by default) onto the buffer's storage, for fast
-- per-element loops in LuaJIT. The pointer keeps its buffer alive (its finalizer holds it), so
-- the collector cannot free the storage under it; buf:release() still ends it. After a dispatch
-- call sn.finish() before reading through it.
local Buffer = debug.getregistry().Buffer.__index
function Buffer.ffi(buf, ctype)
  local kind = buf:type()
  ctype = ctype or ((kind == "uint32" or kind == "uvec4") and "uint32_t*"
                    or (kind == "int32" or kind == "ivec4") and "int32_t*" or "float*")
  return ffi.gc(ffi.cast(ctype, buf:pointer()), function() return buf end)
end

require "shadenet.live"  -- sn.keep, sn.live.*, sn.record
require "shadenet.scene"  -- scene:render
require "shadenet.vec3"  -- sn.vec3 (for lighting twins)

return sn

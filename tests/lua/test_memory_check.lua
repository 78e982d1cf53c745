-- Memory asked for in one large piece is checked against the machine's free memory first
-- (runtime/io/memory.h): a 65536 x 65536 image (64 GiB) was zero-filled until the kernel killed
-- the process. The error names the piece and both sizes.
local sn = require "shadenet"

local meminfo = io.open("/proc/meminfo"):read("*a")
local available = tonumber(meminfo:match("MemAvailable:%s*(%d+) kB")) * 1024
if available > 70 * 2 ^ 30 then
  print("memory check: skipped (" .. available .. " bytes available: a 64 GiB image fits)")
  return
end

local function fails(f, text)
  local ok, err = pcall(f)
  assert(not ok and tostring(err):find(text, 1, true), "expected '" .. text .. "', got: " .. tostring(err))
  return tostring(err)
end
local err = fails(function() local image = sn.image.new { width = 65536, height = 65536 }; return image end,
                  "a 65536x65536 image of 4 channel(s) needs 64.0 GiB of memory; this machine has ")
assert(err:find("GiB available (MemAvailable)", 1, true) and err:find("test_memory_check.lua:", 1, true), err)
if sn.gl_info().software then  -- a software driver's buffers are host memory
  fails(function() local b = sn.buffer { size = 2 ^ 34 }; return b end, "a buffer of 68719476736 bytes needs 64.0 GiB of memory")
end
-- Below the size checked (64 MiB) and within what is free: made as before.
assert(sn.image.new { width = 4096, height = 4096 }:size() == 4096)
print("memory check: ok")

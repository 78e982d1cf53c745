-- Discarded images are collected as a sweep makes them: Lua's collector sees only an image's
-- few userdata bytes, so the runtime tells it of the pixels (lua/binding.h, owned_allocated).
-- 500 discarded 4 MB images must not pile up as 2 GB of garbage.
local sn = require "shadenet"

local function rss_mb()
  local f = assert(io.open("/proc/self/status"))
  local s = f:read("*a")
  f:close()
  return tonumber(s:match("VmRSS:%s*(%d+)")) / 1024
end

collectgarbage()
local before = rss_mb()
local sum = 0
for i = 1, 500 do
  local img = sn.image.new { width = 512, height = 512, channels = 4, fill = i }  -- 4 MB of pixels
  sum = sum + img:get(1, 1)[1]
end
assert(sum == 500 * 501 / 2, "the images' fills sum to " .. sum)
local grown = rss_mb() - before
-- At most 64 MB of garbage between collections, plus what the allocator (or a sanitizer's
-- quarantine, 256 MB) keeps.
assert(grown < 600, string.format("resident memory grew by %.0f MB over 500 discarded 4 MB images", grown))
print(string.format("ok: resident memory grew by %.0f MB", grown))

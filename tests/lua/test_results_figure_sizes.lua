-- docs/experiments.md says how wide the committed figures (docs/results/**/figures/*.png) are at
-- most; the widest one is that wide. (It said "scaled to at most 1000 pixels" while they were
-- committed as the scripts wrote them, up to 2508.)
local sn = require "shadenet"
package.path = "scripts/?.lua;" .. package.path
local results = require "lib.results"

local doc = assert(results.read_file("docs/experiments.md"))
local said = doc:match("The committed results are in `docs/results/NAME/`.-(%d+) pixels wide")
assert(said, "docs/experiments.md no longer says how wide the committed figures are")

-- A PNG's width: the first 4 bytes of its IHDR chunk's data, big-endian.
local function png_width(path)
  local f = assert(io.open(path, "rb"))
  local head = f:read(24)
  f:close()
  assert(head and head:sub(1, 8) == "\137PNG\r\n\26\n", path .. " is not a PNG")
  local a, b, c, d = head:byte(17, 20)
  return ((a * 256 + b) * 256 + c) * 256 + d
end

local widest, widest_path, n = 0, nil, 0
local function walk(dir)
  for _, name in ipairs(sn.fs.list(dir)) do
    local path = dir .. "/" .. name
    if sn.fs.exists(path) == "folder" then walk(path)
    elseif dir:match("/figures$") and name:match("%.png$") then
      n = n + 1
      local w = png_width(path)
      if w > widest then widest, widest_path = w, path end
    end
  end
end
walk("docs/results")
assert(n > 10, "only " .. n .. " committed figures found")
assert(widest == tonumber(said), string.format("docs/experiments.md says the committed figures are at most %s pixels wide; "
                                               .. "%s is %d", said, widest_path, widest))
print(n .. " figures, the widest " .. widest .. " pixels: as docs/experiments.md says")

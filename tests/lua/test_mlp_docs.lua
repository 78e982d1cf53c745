-- Every ```lua block in docs/lua-api/networks.md runs without error.
local path = "docs/lua-api/networks.md"
local f = assert(io.open(path, "r"), path .. " missing")
local text = f:read("*a")
f:close()

local count, pos = 0, 1
while true do
  local s, e, body = text:find("```lua\n(.-)\n```", pos)
  if not s then break end
  local _, newlines = text:sub(1, s):gsub("\n", "")
  local line = newlines + 2
  local chunk, err = loadstring(body, "@" .. path .. ":" .. line)
  assert(chunk, err)
  setfenv(chunk, setmetatable({ print = function() end }, { __index = _G }))
  local ok, msg = pcall(chunk)
  assert(ok, ("%s example at line %d failed: %s"):format(path, line, tostring(msg)))
  count = count + 1
  pos = e + 1
end
assert(count >= 14, "expected at least 14 examples, found " .. count)
print(("%d examples ran"):format(count))

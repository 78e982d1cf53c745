-- Every ```lua block in docs/lua-api.md runs without error (the docs promise runnable examples).
local f = assert(io.open("docs/lua-api.md", "r"), "docs/lua-api.md missing")
local text = f:read("*a")
f:close()

local count, line = 0, 1
local pos = 1
while true do
  local s, e, body = text:find("```lua\n(.-)\n```", pos)
  if not s then break end
  local _, nl = text:sub(1, s):gsub("\n", "")
  line = nl + 2
  count = count + 1
  local chunk, err = loadstring(body, "@docs/lua-api.md:" .. line)
  assert(chunk, err)
  -- run quietly: examples print, the test only cares that they run
  local env = setmetatable({ print = function() end }, { __index = _G })
  setfenv(chunk, env)
  local ok, msg = pcall(chunk)
  assert(ok, ("docs/lua-api.md example at line %d failed: %s"):format(line, tostring(msg)))
  pos = e + 1
end
assert(count >= 10, "expected at least 10 examples, found " .. count)
print(("%d examples ran"):format(count))

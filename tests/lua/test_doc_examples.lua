-- Every ```lua block in docs/lua-api.md and docs/lua-api/meshes.md runs without error (the
-- other chapters have tests of their own that also check the values they promise).
local function run_examples(path)
  local f = assert(io.open(path, "r"), path .. " missing")
  local text = f:read("*a")
  f:close()
  local count, pos = 0, 1
  while true do
    local s, e, body = text:find("```lua\n(.-)\n```", pos)
    if not s then break end
    local _, nl = text:sub(1, s):gsub("\n", "")
    local line = nl + 2
    count = count + 1
    local chunk, err = loadstring(body, "@" .. path .. ":" .. line)
    assert(chunk, err)
    local env = setmetatable({ print = function() end }, { __index = _G })  -- quiet: only errors matter
    setfenv(chunk, env)
    local ok, msg = pcall(chunk)
    assert(ok, ("%s example at line %d failed: %s"):format(path, line, tostring(msg)))
    pos = e + 1
  end
  return count
end

local n = run_examples("docs/lua-api.md")
assert(n >= 10, "expected at least 10 examples in docs/lua-api.md, found " .. n)
local m = run_examples("docs/lua-api/meshes.md")
assert(m >= 10, "expected at least 10 examples in docs/lua-api/meshes.md, found " .. m)
print(("%d + %d examples ran"):format(n, m))

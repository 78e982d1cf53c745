-- Every ```lua block in docs/lua-api/networks-gl.md runs without error.
local path = "docs/lua-api/networks-gl.md"
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
  local printed = {}
  setfenv(chunk, setmetatable({ print = function(...)
    local parts = {}
    for i = 1, select("#", ...) do parts[i] = tostring((select(i, ...))) end
    printed[#printed + 1] = table.concat(parts, " ")
  end }, { __index = _G }))
  local ok, msg = pcall(chunk)
  assert(ok, ("%s example at line %d failed: %s"):format(path, line, tostring(msg)))
  count = count + 1
  pos = e + 1
  -- the `-->` results the text promises, where they are exact
  if line > 0 and body:find("print%(sn.mlp_weight_uploads") then
    assert(printed[1] == "1 0", "weight edit example printed " .. tostring(printed[1]))
  end
  if body:find("adam = { lr = 1e15 }") then
    assert(printed[1] == "2 nil 25", "divergence example printed " .. tostring(printed[1]))
  end
end
assert(count >= 5, "expected at least 5 examples, found " .. count)
print(("%d examples ran"):format(count))

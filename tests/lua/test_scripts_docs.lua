-- Every ```lua block in docs/lua-api/experiments.md runs without error.
local path = "docs/lua-api/experiments.md"
local f = assert(io.open(path, "r"), path .. " missing")
local text = f:read("*a")
f:close()
local count, pos = 0, 1
local saved_path = package.path
while true do
  local s, e, body = text:find("```lua\n(.-)\n```", pos)
  if not s then break end
  local _, nl = text:sub(1, s):gsub("\n", "")
  count = count + 1
  local chunk, err = loadstring(body, "@" .. path .. ":" .. (nl + 2))
  assert(chunk, err)
  setfenv(chunk, setmetatable({ print = function() end }, { __index = _G }))
  local ok, msg = pcall(chunk)
  assert(ok, ("%s example at line %d failed: %s"):format(path, nl + 2, tostring(msg)))
  package.path = saved_path
  pos = e + 1
end
assert(count >= 10, "expected at least 10 examples, found " .. count)
os.execute("rm -rf out/demo out/sweep_demo out/my_phong_check")
print(count .. " examples ran")

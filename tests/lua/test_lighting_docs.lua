-- Every ```lua block in docs/lua-api/ground-truth.md runs without error, and the values its
-- comments promise hold (checked below for the ones that print numbers).
local path = "docs/lua-api/ground-truth.md"
local f = assert(io.open(path, "r"), path .. " missing")
local text = f:read("*a")
f:close()
local count, pos = 0, 1
local printed = {}
while true do
  local s, e, body = text:find("```lua\n(.-)\n```", pos)
  if not s then break end
  local _, nl = text:sub(1, s):gsub("\n", "")
  count = count + 1
  local chunk, err = loadstring(body, "@" .. path .. ":" .. (nl + 2))
  assert(chunk, err)
  local out = {}
  setfenv(chunk, setmetatable({ print = function(...)
    local parts = {}
    for i = 1, select("#", ...) do parts[i] = tostring((select(i, ...))) end
    out[#out + 1] = table.concat(parts, "\t")
  end }, { __index = _G }))
  local ok, msg = pcall(chunk)
  assert(ok, ("%s example at line %d failed: %s"):format(path, nl + 2, tostring(msg)))
  printed[count] = out
  pos = e + 1
end
assert(count >= 10, "expected at least 10 examples, found " .. count)

local function has(block, pattern)
  for _, line in ipairs(printed[block]) do
    if line:match(pattern) then return true end
  end
  error(("example %d printed nothing matching %q:\n%s"):format(block, pattern, table.concat(printed[block], "\n")))
end
has(1, "^ggx%(roughness=0%.3, f0={1, 0%.71, 0%.29}, diffuse={0, 0, 0}, ambient={0%.1, 0%.1, 0%.1}%)$")
has(1, "^0%.45$")
has(4, "^0%.3\t0%.5\t0%.7")
has(6, "^37800\t0$")
-- "Your own lighting model": the defined model's twin at the terminator, its check and stress.
has(7, "^wrap_lambert%(albedo={0%.8, 0%.8, 0%.8}, w=0%.3%)$")
has(7, "^0%.184615384615")
has(7, "^true\t0$")
has(7, "^1600\t400$")
has(8, "^53%.24%d*\t80%.09%d*\t67%.20%d*$")
has(9, "^0%.1666")
os.execute("rm -f out/cloth_ggx.png out/duck_normals.exr out/quad.glb")
print(count .. " examples ran")

-- Every ```lua block in docs/lua-api/ground-truth.md runs without error, and the values its
-- comments promise hold (doc_examples checks each "-->"; below, what the examples print besides).
local docs = require "doc_examples"
local printed = {}
local count = docs.run("docs/lua-api/ground-truth.md", 10, function(_, out) printed[#printed + 1] = out end)

local function has(block, pattern)
  for _, line in ipairs(printed[block]) do
    if line:match(pattern) then return true end
  end
  error(("example %d printed nothing matching %q:\n%s"):format(block, pattern, table.concat(printed[block], "\n")))
end
has(1, "^ggx%(roughness=0%.3, f0={1, 0%.71, 0%.29}, diffuse={0, 0, 0}, ambient={0%.1, 0%.1, 0%.1}%)$")
has(1, "^0%.45$")
has(4, "^0%.3 0%.5 0%.7")
has(6, "^37800 0$")
-- "Your own lighting model": the defined model's twin at the terminator, its check and stress.
has(7, "^wrap_lambert%(albedo={0%.8, 0%.8, 0%.8}, w=0%.3%)$")
has(7, "^0%.184615384615")
has(7, "^true 0$")
has(7, "^1600 400$")
has(8, "^53%.24%d* 80%.09%d* 67%.20%d*$")
has(9, "^0%.1666")
os.execute("rm -f out/cloth_ggx.png out/duck_normals.exr out/quad.glb")
print(count .. " examples ran")

-- Every ```lua block in docs/lua-api/datasets.md runs as it is, and the values its comments
-- promise hold for the ones checked here.
local docs = require "doc_examples"

local outputs = {}
local count = docs.run("docs/lua-api/datasets.md", 5, function(_, printed) outputs[#outputs + 1] = printed end)

local function has(pattern)
  for _, lines in ipairs(outputs) do
    for _, line in ipairs(lines) do
      if line:match(pattern) then return end
    end
  end
  error("no example printed a line matching " .. pattern)
end
has("^Dataset%(6 %-> 3 rgb, 4000 train / 1000 val%) 4000 1000$")
has("^Dataset%(6 %-> 3 rgb, 80 train / 20 val%) 80 20$")
has("^2 1 2 2$")
-- Coverage: the cloth fills about a third of the normal sphere, and most of a sphere lies outside it.
has("^normals: 3%d%% of bins, highest y 0%.[34]%d; views: 4%d%%; sphere rows outside: [56]%d%%$")
print(count .. " examples ran")

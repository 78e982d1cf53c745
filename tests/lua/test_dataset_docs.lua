-- Every ```lua block in docs/lua-api/datasets.md runs as it is, and the values its comments
-- promise hold for the ones checked here.
local docs = require "doc_examples"

local outputs = {}
local count = docs.run("docs/lua-api/datasets.md", 11, function(_, printed) outputs[#outputs + 1] = printed end)

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
-- Combining, saving and loading
has("^Dataset%(6 %-> 3 rgb, 4000 train / 1000 val%)$")
has("^sn%.dataset%.concat: dataset 2 has colour space hsv, dataset 1 has rgb$")
has("^Dataset%(6 %-> 3 rgb, 80 train / 20 val%)$")
has("^Dataset%(6 %-> 3 rgb, 400 train / 100 val%)$")
has("^true 400 100$")
has("^5 5$")
has("^9 1$")
has("^out/docs_cloth%.json Dataset%(6 %-> 3 rgb, 4000 train / 1000 val%)$")
has("^true$")
has("^normal_x,normal_y,normal_z,uv_u,uv_v,h,s,v,set$")
has("^0,0,1,0%.25,0%.5,0%.1,0%.2,0%.3,train$")
has("^0,1,0,0%.75,0%.1,1,0%.5,0,val$")
has("^Dataset%(5 %-> 3 hsv, 1 train / 1 val%)$")
-- Sampling the domain
has("^Dataset%(6 %-> 3 rgb, 2400 train / 600 val%) 2400 600$")
has("^mean n%.v 0%.67$")
-- Coverage: the cloth fills about a third of the normal sphere, and most of a sphere lies outside it.
has("^normals: 3%d%% of bins, highest y 0%.[34]%d; views: 4%d%%; sphere rows outside: [56]%d%%$")
print(count .. " examples ran")

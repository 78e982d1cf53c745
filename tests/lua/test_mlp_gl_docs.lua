-- Every ```lua block in docs/lua-api/networks-gl.md runs, and prints the `-->` results the
-- text promises where they are exact.
local docs = require "doc_examples"

local n = docs.run("docs/lua-api/networks-gl.md", 7, function(body, printed)
  if body:find("print%(sn.render_info%(%).backend") then
    local want = { "cpu 0", "true", "true", "true" }
    for i, w in ipairs(want) do
      assert(printed[i] == w, ("backends example line %d printed %s"):format(i, tostring(printed[i])))
    end
  end
  if body:find("print%(sn.mlp_weight_uploads") then
    assert(printed[1] == "1 0", "weight edit example printed " .. tostring(printed[1]))
  end
  if body:find("sn.render_errors {") then
    assert(printed[1] == "true" and printed[2] == "true 0", "render_errors example printed " ..
           tostring(printed[1]) .. " / " .. tostring(printed[2]))
  end
  if body:find("adam = { lr = 1e15 }") then
    assert(printed[1] == "2 nonfinite nil 25", "divergence example printed " .. tostring(printed[1]))
  end
end)
print(("%d examples ran"):format(n))

-- Every ```lua block of the API docs runs without error and prints what its "-->" comments
-- promise (docs/lua-api/networks-gl.md, ground-truth.md, datasets.md, experiments.md and live.md
-- have tests of their own).
local docs = require "doc_examples"

local counts = {
  docs.run("docs/lua-api.md", 10),
  docs.run("docs/lua-api/meshes.md", 10),
  docs.run("docs/lua-api/networks.md", 12),
}
print(("%s examples ran"):format(table.concat(counts, " + ")))
-- The Markdown no test runs the examples of: its code blocks are closed.
for _, path in ipairs { "README.md", "docs/experiments.md", "docs/lighting.md", "docs/live-mode.md",
                        "docs/performance.md", "docs/reliability.md", "docs/lua-api/ground-truth.md",
                        "docs/lua-api/live.md", "docs/lua-api/experiments.md", "docs/lua-api/networks-gl.md" } do
  docs.check_fences(path)
end

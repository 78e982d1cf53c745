-- Every ```lua block in docs/lua-api/experiments.md runs as it is (tests/lua/doc_examples.lua).
local docs = require "doc_examples"
local n = docs.run("docs/lua-api/experiments.md", 10)
os.execute("rm -rf out/demo out/sweep_demo out/my_phong_check out/my_typo")
print(n .. " examples ran")

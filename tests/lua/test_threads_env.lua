-- SHADENET_THREADS is checked: a value that is not a whole number of threads in 1..1024 is an
-- error naming it ("abc" and 0 ran on every core without a word), and a good one is used.
local C = require "script_check"

local child = C.child("threads_env", [[
local sn = require "shadenet"
local data = sn.dataset { x = { { 0.1, 0.2 }, { 0.3, 0.4 }, { 0.5, 0.6 }, { 0.7, 0.8 } },
                          y = { { 0.1, 0.1, 0.1 }, { 0.2, 0.2, 0.2 }, { 0.3, 0.3, 0.3 }, { 0.4, 0.4, 0.4 } }, split = 0.5 }
local r = sn.train { nets = { sn.mlp { inputs = 2, hidden = { 4 }, seed = 1 } }, data = data, epochs = 1, batch = 2,
                     backend = "cpu" }
print(("trained %.9g"):format(r[1].val_mse[1] or r[1].train_mse[1]))
]])

for _, bad in ipairs { "abc", "0", "-2", "2x", "1.5", "20000" } do
  local code, out = C.run(child, {}, { SHADENET_THREADS = bad })
  assert(code ~= 0, "SHADENET_THREADS=" .. bad .. " was accepted:\n" .. out)
  assert(out:find("SHADENET_THREADS='" .. bad .. "' is not a whole number of threads in 1..1024", 1, true), out)
  assert(out:find("child.lua:4:", 1, true), "the error names the script's line:\n" .. out)
end
local outs = {}
for _, good in ipairs { "1", "2", "" } do
  local code, out = C.run(child, {}, { SHADENET_THREADS = good })
  assert(code == 0, "SHADENET_THREADS=" .. good .. ":\n" .. out)
  outs[#outs + 1] = out:match("trained (%S+)")
end
assert(outs[1] and outs[1] == outs[2] and outs[2] == outs[3], "threads do not change the numbers: " .. table.concat(outs, " "))
print("threads env: ok")

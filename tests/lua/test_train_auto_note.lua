-- sn.train's note on the backend auto picks comes when it is picked, before the training (it
-- came after, below a sweep's finished progress line), and once per process.
local C = require "script_check"
local results = require "lib.results"

local dir = C.tmpdir("auto_note")
local script = dir .. "/train.lua"
results.write_file(script, [[
local sn = require "shadenet"
local data = sn.dataset.sample { target = sn.lighting.phong {}, n = 200 }
for _ = 1, 2 do
  sn.train { nets = sn.mlp { inputs = 6, hidden = { 4 }, outputs = 3 }, data = data, epochs = 2,
             progress = function(e) print("epoch " .. e.epoch) io.stdout:flush() end }
end
]])
local code, out = C.run(script)
assert(code == 0, out)
local note = out:find("sn.train: backend auto -> cpu (", 1, true)
assert(note and note < out:find("epoch 1", 1, true), "the note before the first epoch:\n" .. out)
assert(not out:find("backend auto", note + 30, true), "said once:\n" .. out)
C.rm(dir)
print("ok")

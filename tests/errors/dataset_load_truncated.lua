-- expect: dataset_load_truncated\.lua:13: sn\.dataset\.load: .*/d\.inputs\.npy: 100 data bytes, but shape \(10, 3\) of float32 needs 120 \(truncated\)
local sn = require "shadenet"
local x, y = {}, {}
for i = 1, 10 do x[i], y[i] = { i, 0, 1 }, { 0.5, 0.5, 0.5 } end
local dir = sn.fs.tempdir("error")
local path = sn.dataset { x = x, y = y }:export(dir .. "/d")
-- Cut the last five floats off the inputs, as an interrupted copy would.
local f = assert(io.open(dir .. "/d.inputs.npy", "rb"))
local bytes = f:read("*a")
f:close()
f = assert(io.open(dir .. "/d.inputs.npy", "wb"))
f:write(bytes:sub(1, #bytes - 20)) f:close()
local ok, err = pcall(function() local d = sn.dataset.load(path) return d end)
error(err, 0)

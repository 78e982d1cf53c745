-- expect: dataset_load_bad_csv\.lua:7: sn\.dataset\.load: .*\.csv:3: column 'g': '0\.5x' is not a number
local sn = require "shadenet"
local path = sn.fs.tempdir("error") .. "/bad.csv"
local f = assert(io.open(path, "w"))
f:write("normal_x,normal_y,normal_z,r,g,b,set\n0,0,1,0.5,0.5,0.5,train\n0,1,0,0.5,0.5x,0.5,val\n")
f:close()
local ok, err = pcall(function() local d = sn.dataset.load(path) return d end)
error(err, 0)

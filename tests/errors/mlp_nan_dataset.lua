-- expect: mlp_nan_dataset\.lua:6: sn\.dataset option 'y' row 7 column 2 is NaN
local sn = require "shadenet"
local x, y = {}, {}
for i = 1, 20 do x[i] = {1, 2, 3, 4, 5, i} y[i] = {0, 0, 0} end
y[7][2] = 0 / 0
local data = sn.dataset { x = x, y = y }

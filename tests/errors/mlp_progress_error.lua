-- expect: mlp_progress_error\.lua:7: sn\.train: the progress function failed: .*mlp_progress_error\.lua:8: stop here
local sn = require "shadenet"
local x, y = {}, {}
for i = 1, 20 do x[i] = {1, 2, 3, 4, 5, i} y[i] = {0, 0, 0} end
local data = sn.dataset { x = x, y = y }
local net = sn.mlp { inputs = 6, hidden = {8} }
sn.train { nets = { net }, data = data, epochs = 3, progress = function(e)
  if e.epoch == 2 then error("stop here") end
end }

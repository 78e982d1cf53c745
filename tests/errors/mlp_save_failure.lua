-- expect: cannot write checkpoint '.*/net\.snmlp': cannot create folder .*: Not a directory
local sn = require "shadenet"
local blocker = sn.fs.write(sn.fs.tempdir("error") .. "/blocker", "")  -- a file: nothing can be saved below it
local net = sn.mlp { inputs = 6, hidden = {8} }
local ok, err = pcall(net.save, net, blocker .. "/net.snmlp")
error(err, 0)

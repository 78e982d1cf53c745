-- expect: truncated_net\.snmlp: checkpoint is truncated \([0-9]+ of [0-9]+ bytes\)
local sn = require "shadenet"
local path = sn.fs.tempdir("error") .. "/truncated_net.snmlp"
sn.mlp { inputs = 6, hidden = {8} }:save(path)
local f = io.open(path, "rb") local bytes = f:read("*a") f:close()
f = io.open(path, "wb") f:write(bytes:sub(1, #bytes - 7)) f:close()
local ok, err = pcall(sn.load, path)
error(err, 0)

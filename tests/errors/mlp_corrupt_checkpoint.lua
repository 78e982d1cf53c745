-- expect: corrupt_net\.snmlp: checkpoint is corrupt \(checksum mismatch\)
local sn = require "shadenet"
local path = sn.fs.tempdir("error") .. "/corrupt_net.snmlp"
sn.mlp { inputs = 6, hidden = {8} }:save(path)
local f = io.open(path, "rb") local bytes = f:read("*a") f:close()
local i = #bytes - 20  -- flip one byte of a weight
bytes = bytes:sub(1, i - 1) .. string.char((bytes:byte(i) + 1) % 256) .. bytes:sub(i + 1)
f = io.open(path, "wb") f:write(bytes) f:close()
local ok, err = pcall(sn.load, path)
error(err, 0)  -- the message itself names the file and the fault

-- expect: inf_net\.snmlp: checkpoint refused: its layer 2 weight\[3\]\[5\] \(parameter 59 of 63\) is infinite
-- A checkpoint whose checksum is valid but whose numbers are not (written by another tool, or
-- by a build that saved a diverged network) is refused, naming the first bad parameter.
local sn = require "shadenet"
local ffi = require "ffi"
local path = sn.fs.tempdir("error") .. "/inf_net.snmlp"
local net = sn.mlp { inputs = 6, hidden = { 6 }, outputs = 3 }
net.layers[2].weight[3][5] = 1234.5  -- a marker: its float bytes are found and replaced below
net:save(path)
local f = io.open(path, "rb") local bytes = f:read("*a") f:close()
local mark = ffi.new("float[1]", 1234.5)
local at = bytes:find(ffi.string(mark, 4), 25, true)
bytes = bytes:sub(1, at - 1) .. "\0\0\128\127" .. bytes:sub(at + 4)  -- +infinity
-- The FNV-1a 64 checksum of the payload (from byte 25), as the file format says (nn/checkpoint.h).
local h = 0xcbf29ce484222325ULL
for i = 25, #bytes do h = bit.bxor(h, bytes:byte(i)) * 0x100000001b3ULL end
local sum = ffi.new("uint64_t[1]", h)
bytes = bytes:sub(1, 16) .. ffi.string(sum, 8) .. bytes:sub(25)
f = io.open(path, "wb") f:write(bytes) f:close()
local ok, err = pcall(sn.load, path)
error(err, 0)

-- What a user's encoding (sn.encoding.define) costs the cpu backend: its Lua twin encodes the
-- dataset's rows once per training run, on the script's thread only. One network of 2 hidden
-- layers of 8 (2x8), one epoch of 64,000 sampled rows (normal and view, both encoded with 4
-- bands), with the built-in frequency encoding, with a Lua copy of it
-- (examples/lua_frequency.lua), and without encodings; the difference to the latter is the
-- encoding's cost.
--
--   shadenet bench/encoding_twin.lua [repeats]      best of `repeats` (default 3), wall and CPU time
--
-- Ctrl-C stops it after the training in flight (that row is not printed) and exits 130.
local sn = require "shadenet"
package.path = (arg[0]:match("^(.*)/[^/]*$") or ".") .. "/?.lua;" .. package.path
local B = require "common"
local repeats = B.args("bench/encoding_twin.lua", { { "repeats", "3", B.whole(1) } }).repeats
B.catch_interrupt()

package.path = B.dir .. "/../examples/?.lua;" .. package.path
require "lua_frequency"  -- defines lua_frequency: the built-in frequency encoding as a Lua definition

local rows = 64000
local data = sn.dataset.sample { target = sn.lighting.phong {}, n = rows, seed = 1 }
local function run(kind)
  local enc = kind and { normal = { kind, bands = 4 }, view = { kind, bands = 4 } } or nil
  local wall, cpu = math.huge, math.huge
  for _ = 1, repeats do
    local net = sn.mlp { inputs = { "normal", "view" }, hidden = { 8, 8 }, encoding = enc, seed = 1 }
    local t0, c0 = sn.clock(), os.clock()
    sn.train { nets = net, data = data, epochs = 1, backend = "cpu" }
    wall, cpu = math.min(wall, sn.clock() - t0), math.min(cpu, os.clock() - c0)
    B.stop_if_interrupted("the encoding " .. (kind or "none") .. " (cut short)")
  end
  return wall, cpu
end

print("load: " .. B.load())
local w0, c0 = run(nil)
print(("%-14s %8s %8s %14s"):format("encoding", "wall s", "cpu s", "us/row (wall)"))
print(("%-14s %8.3f %8.3f %14s"):format("none", w0, c0, "-"))
for _, k in ipairs { "frequency", "lua_frequency" } do
  local w, c = run(k)
  print(("%-14s %8.3f %8.3f %14.2f"):format(k, w, c, (w - w0) / rows * 1e6))
end

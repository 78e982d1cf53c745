-- SHADENET_GL_KERNEL forces the gl trainer's kernel where a script leaves it automatic: per_net
-- and per_sample train the same network to curves that agree closely but not to the bit (their
-- sums run in other orders), "auto" and no setting train as the device's rule picks (per_net for a
-- small network on a CPU renderer, per_sample on a GPU), and an unknown name names the valid ones.
local sn = require "shadenet"
local C = require "script_check"

local child, base = C.child("gl_kernel", [[
local sn = require "shadenet"
local scene = sn.scene { mesh = "meshes/test_blob.glb", size = { 64, 48 }, views = { count = 2, elevation = 20 } }
local data = scene:dataset { inputs = { "normal", "view" }, target = sn.lighting.phong {}, split = 0.8, seed = 3 }
local net = sn.mlp { inputs = 6, hidden = { 8, 8 }, seed = 5 }
local job = sn.train { nets = { net }, data = data, epochs = 2, batch = 8, adam = { lr = 3e-3 }, seed = 9, backend = "gl" }
local r = job[1]
print(("curve %.17g %.17g"):format(r.val_mse[1], r.val_mse[2]))
print("device " .. r.device)
]])

local function curve(kernel)
  local code, out = C.run(child, {}, kernel and { SHADENET_GL_KERNEL = kernel } or nil)
  assert(code == 0, "SHADENET_GL_KERNEL=" .. tostring(kernel) .. ":\n" .. out)
  local a, b = out:match("curve (%S+) (%S+)")
  -- The records name the kernel: their numbers differ, so they are not one device's.
  local named = out:match("device [^\n]*, (%S+) kernel\n")
  assert(named == (kernel == "per_net" or kernel == "per_sample") and kernel or named, out)
  return { tonumber(a), tonumber(b) }, a .. " " .. b, named
end

local per_net, per_net_bits = curve("per_net")
local per_sample, per_sample_bits = curve("per_sample")
assert(per_net_bits ~= per_sample_bits, "the two kernels sum in other orders; the same bits mean one kernel ran twice")
for e = 1, 2 do
  assert(math.abs(per_net[e] - per_sample[e]) <= 1e-5 * per_net[e], ("epoch %d: %.9g vs %.9g"):format(e, per_net[e], per_sample[e]))
end
local rule = sn.gl_info().software and per_net_bits or per_sample_bits
assert(select(2, curve(nil)) == rule and select(2, curve("auto")) == rule, "automatic: the device's rule")
assert(select(3, curve(nil)) == (sn.gl_info().software and "per_net" or "per_sample"), "and names the kernel it picked")
assert(select(2, curve("")) == rule, "an empty setting is no setting")

local code, out = C.run(child, {}, { SHADENET_GL_KERNEL = "per_batch" })
assert(code ~= 0 and out:find("SHADENET_GL_KERNEL='per_batch': unknown gl training kernel (valid: auto, per_sample, per_net)", 1, true), out)
assert(out:find("child.lua:5:", 1, true), "the error names the script's line:\n" .. out)
C.rm(base)
print("ok")

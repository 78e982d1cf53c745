-- The lighting examples run from a fresh process and write their figures: the two models defined
-- in Lua + GLSL (each checks its shader against its twin, stresses it, trains a network) and the
-- network conditioned on GGX roughness (its table holds five rows of finite image MSEs).
local sn = require "shadenet"
local shadenet = arg and arg[-1] or "shadenet"
local out = "out/lighting_examples"
os.execute(("rm -rf %q"):format(out))

local function run(script, dir)
  local log = dir .. ".log"
  local cmd = ("%q %s %q > %q 2>&1"):format(shadenet, script, dir, log)
  local ok = os.execute(cmd)
  local f = io.open(log, "r")
  local text = f and f:read("*a") or ""
  if f then f:close() end
  assert(ok == 0 or ok == true, script .. " failed:\n" .. text)
  return text
end

sn.fs.mkdir(out)
for _, name in ipairs { "oren_nayar", "aniso_ggx" } do
  local text = run("examples/lighting/" .. name .. ".lua", out)
  local diff = tonumber(text:match("largest difference ([%d%.e%-]+)"))
  assert(diff and diff < 1e-4, name .. ": GPU vs twin " .. tostring(diff))
  assert(text:find("stress test: 37800 samples, 0 failures", 1, true), name .. ": stress\n" .. text)
  local mse = tonumber(text:match("image MSE on the unseen meshes ([%d%.e%-]+)"))
  assert(mse and mse < 0.05, name .. ": unseen image MSE " .. tostring(mse))
  local img = sn.image.load(out .. "/" .. name .. ".png")
  assert(select(1, img:size()) > 500, name .. ": the figure")
end

local text = run("examples/conditional_ggx.lua", out .. "/conditional")
local rows = 0
for r, mse, alone in text:gmatch("roughness ([%d%.]+): image MSE ([%d%.e%-]+) %(a network for this roughness alone: ([%d%.e%-]+)%)") do
  rows = rows + 1
  assert(tonumber(mse) < 0.02 and tonumber(alone) < 0.02, ("roughness %s: %s / %s"):format(r, mse, alone))
end
assert(rows == 5, "five roughnesses:\n" .. text)
assert(sn.load(out .. "/conditional/conditional_ggx.snmlp"):conditions()[1].name == "roughness", "the saved network")
print("ok")

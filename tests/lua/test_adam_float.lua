-- Adam as the kernels run it, in float, at its edges (both backends):
-- * a beta near 1 (0.9999999, 0.999999): the first step moves every weight by lr (Adam's first
--   step is lr * g / |g|); the bias corrections were computed from the double betas while the
--   moments used the float ones, and the step was 1.83 lr;
-- * settings that round to 1 or 0 in float are refused (they trained nothing, or blew up);
-- * squared errors of 4.9e37: the cpu validation MSE is finite, as gl's (it summed 8 lanes in
--   float, overflowed, and flagged an "exploded" net that gl trained on).
local sn = require "shadenet"
local fails = require("expect").fails

local x, y = {}, {}
for i = 1, 40 do
  local a, b = math.sin(i), math.cos(i * 1.3)
  x[i], y[i] = { a, b }, { 0.5 + 0.4 * a * b }
end
local data = sn.dataset { x = x, y = y }  -- 32 training rows: one step of batch 32 per epoch

for _, backend in ipairs(sn.backends()) do
  for _, betas in ipairs { { 0.9, 0.9999999 }, { 0.999999, 0.9 }, { 0.9, 0.999 } } do
    local net = sn.mlp { inputs = 2, hidden = { 1 }, outputs = 1, seed = 3 }
    local p0 = net:params()
    sn.train { nets = net, data = data, epochs = 1, batch = 32, backend = backend,
               adam = { lr = 1e-2, beta1 = betas[1], beta2 = betas[2] } }
    for i, v in ipairs(net:params()) do
      local moved = math.abs(p0[i] - v) / 1e-2
      assert(math.abs(moved - 1) < 1e-3, ("%s betas %g, %g: parameter %d moved %.6f lr, not lr"):format(
        backend, betas[1], betas[2], i, moved))
    end
  end
end

local net = sn.mlp { inputs = 2, hidden = { 1 }, outputs = 1 }
fails(function() sn.train { nets = net, data = data, adam = { beta1 = 0.99999999 } } end,
      "adam beta1 must be in [0, 1) as a float")
fails(function() sn.train { nets = net, data = data, adam = { lr = 1e-50 } } end, "adam lr must be a normal float")
if sn.backends()[2] then
  -- The gl backend's table of bias corrections would need 1.7e8 entries (3 GB): refused first.
  fails(function() sn.train { nets = net, data = data, epochs = 2 ^ 31 - 1, batch = 4, backend = "gl",
                              adam = { beta1 = 0.9999999 } } end, "bias corrections, above its 2^25")
end

local huge = {}
for i = 1, 40 do huge[i] = { 7e18 } end
local far = sn.dataset { x = x, y = huge }
local seen = {}
for _, backend in ipairs(sn.backends()) do
  local n = sn.mlp { inputs = 2, hidden = { 3 }, outputs = 1, seed = 1 }
  local r = sn.train { nets = n, data = far, epochs = 1, batch = 4, backend = backend }[1]
  assert(r.val_mse[1] > 4e37 and r.val_mse[1] < math.huge and not r.diverged,
         ("%s: val MSE %g, %s"):format(backend, r.val_mse[1], r.diverged and r.diverged.reason or "not flagged"))
  seen[#seen + 1] = r.val_mse[1]
end
assert(#seen < 2 or math.abs(seen[1] - seen[2]) <= 1e-5 * seen[1], "cpu and gl agree: " .. table.concat(seen, ", "))
print("ok")

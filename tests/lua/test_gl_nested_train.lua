-- A gl training job nested in another's progress function (allowed: only the same net is
-- refused) leaves the outer job's results as they are. Both jobs' kernels are one cached
-- Program for the same architecture; the outer job set its Adam uniforms (beta1, beta2, eps and
-- the length of its bias-correction table) once, and the inner job's values replaced them: the
-- outer curve changed from its second epoch on. Each dispatch now sets its own job's values.
local sn = require "shadenet"

local x, y = {}, {}
for i = 1, 160 do x[i] = { math.sin(i), math.cos(i), 0.5 } y[i] = { 0.3 + 0.1 * math.sin(i), 0.5, 0.1 } end
local data = sn.dataset { x = x, y = y }

local function outer_curve(inner)
  local net = sn.mlp { inputs = 3, hidden = { 4 }, seed = 1 }
  local progress = inner and function()
    -- Same architecture (the same cached Program), other Adam settings and a shorter job.
    sn.train { nets = sn.mlp { inputs = 3, hidden = { 4 }, seed = 3 }, data = data, epochs = 1, backend = "gl",
               adam = { lr = 0.05, beta1 = 0.5, beta2 = 0.7, eps = 1e-3 } }
  end
  local r = sn.train { nets = net, data = data, epochs = 3, backend = "gl", progress = progress }[1]
  return table.concat(r.val_mse, " ")
end

local alone, nested = outer_curve(nil), outer_curve(true)
assert(alone == nested, "the nested job changed the outer curve:\n  alone  " .. alone .. "\n  nested " .. nested)
print("gl nested train: ok (" .. alone .. ")")

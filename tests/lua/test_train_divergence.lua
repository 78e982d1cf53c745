-- One divergence rule on both backends (docs/reliability.md, "The divergence rule"): a run
-- whose learning rate blows it up is flagged at the same epoch and step, for the same reason,
-- on cpu and gl; the flagged net keeps finite weights and can be saved.
local sn = require "shadenet"

local xs, ys = require("smooth_rows")(3000)
local data = sn.dataset { x = xs, y = ys, split = 0.8, seed = 1 }
local steps = 2400 / 8

-- lr = 1e3: the validation MSE goes from 0.41 to ~1e6 in epoch 1, above 100 x its best (the
-- untrained net's) and the constant predictor's. lr = 1e15: at step 2 a sample's squared error is
-- ~1e31, past the bound on samples (1e12 x the reference), before float overflow. lr = 1e37:
-- the first update leaves weights of ~1e37, and the second step's forward pass overflows. (An lr
-- past float's range, 1e39, is refused before training: it was infinite in the kernels.)
local cases = {
  { lr = 1e3, epoch = 1, step = steps, reason = "exploded", trained = steps },
  { lr = 1e15, epoch = 1, step = 2, reason = "exploded", trained = 1 },
  { lr = 1e37, epoch = 1, step = 2, reason = "nonfinite", trained = 1 },
}
local tmp = sn.fs.tempdir("test_train_divergence") .. "/net.snmlp"
for _, c in ipairs(cases) do
  local seen = {}
  for _, backend in ipairs(sn.backends()) do
    local net = sn.mlp { inputs = 6, hidden = { 12, 12 }, outputs = 3, seed = 4 }
    local r = sn.train { nets = net, data = data, epochs = 4, backend = backend, adam = { lr = c.lr } }[1]
    local d = r.diverged
    local got = d and string.format("%d/%d %s", d.epoch, d.step, d.reason) or "not flagged"
    assert(got == string.format("%d/%d %s", c.epoch, c.step, c.reason), backend .. " lr " .. c.lr .. ": " .. got)
    assert(r.steps == c.trained and net:trained_steps() == c.trained, backend .. ": steps " .. r.steps)
    assert(r.interrupted == nil)
    assert(r.initial_val_mse > 0.3 and r.initial_val_mse < 0.5, "the untrained net's MSE " .. r.initial_val_mse)
    for _, v in ipairs(net:params()) do assert(v == v and v > -math.huge and v < math.huge, "finite weights") end
    net:save(tmp)  -- a flagged net is still a finite one
    seen[#seen + 1] = got
  end
  print(("lr %g: %s"):format(c.lr, table.concat(seen, ", ")))
end

-- divergence_factor = math.huge turns the explosion rules off: lr = 1e3 trains every epoch.
for _, backend in ipairs(sn.backends()) do
  local net = sn.mlp { inputs = 6, hidden = { 12, 12 }, outputs = 3, seed = 4 }
  local r = sn.train { nets = net, data = data, epochs = 2, backend = backend, adam = { lr = 1e3 },
                       divergence_factor = math.huge }[1]
  assert(r.diverged == nil and #r.val_mse == 2 and r.val_mse[1] > 1e4, backend .. ": the rule is off")
end

-- A healthy run is never flagged, on either backend.
for _, backend in ipairs(sn.backends()) do
  local r = sn.train { nets = sn.mlp { inputs = 6, hidden = { 12, 12 }, outputs = 3, seed = 4 }, data = data,
                       epochs = 6, backend = backend, adam = { lr = 3e-3 } }[1]
  assert(r.diverged == nil and r.epochs == 6, backend .. ": a healthy run")
end
-- A saturated unit is not a divergence: gelu far below 0 gives f = 0 and f' = 0, where its f'
-- was 0 * inf = NaN past |z| = 1.8e19 on both backends and the first step was flagged.
local one_row = sn.dataset { x = { { 1 }, { 1 } }, y = { { 0.5 }, { 0.5 } }, split = 0.5 }
for _, backend in ipairs(sn.backends()) do
  for _, z in ipairs { -2e19, -1e30 } do
    local net = sn.mlp { inputs = 1, hidden = { 1 }, outputs = 1, activation = "gelu" }
    net:set_params { z, 0, 1, 0 }
    local w = net:params()[1]  -- z as a float
    local r = sn.train { nets = net, data = one_row, epochs = 1, batch = 1, backend = backend }[1]
    assert(r.diverged == nil and r.steps == 1 and net:params()[1] == w,
           ("%s gelu at z = %g: %s"):format(backend, z, r.diverged and r.diverged.reason or "weight moved"))
  end
end
print("train divergence: ok")

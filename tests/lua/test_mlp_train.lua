-- Training from Lua on the cpu backend: results, determinism, keep = "best", progress, weights
-- committed to the nets, dead-unit diagnostics.
local sn = require "shadenet"

-- A smooth 6 -> 3 target, like a lighting model of normal and view.
local xs, ys = require("smooth_rows")(3000)
local data = sn.dataset { x = xs, y = ys, split = 0.8, seed = 1, input_names = {"normal", "view"} }
local ntrain, nval = data:counts()
assert(ntrain == 2400 and nval == 600, "split " .. ntrain .. "/" .. nval)
assert(tostring(data) == "Dataset(6 -> 3 rgb, 2400 train / 600 val)", tostring(data))
-- Every row went to exactly one side: the targets' sums agree.
local total, split_total = 0, 0
for i = 1, 3000 do total = total + ys[i][1] end
for i = 1, ntrain do local _, y = data:row("train", i) split_total = split_total + y[1] end
for i = 1, nval do local _, y = data:row("val", i) split_total = split_total + y[1] end
assert(math.abs(total - split_total) < 1e-3, "split keeps every row once")

-- The constant predictor's MSE (the variance of the validation targets).
local var = 0
for o = 1, 3 do
  local mean, sq = 0, 0
  for i = 1, nval do local _, y = data:row("val", i) mean = mean + y[o] end
  mean = mean / nval
  for i = 1, nval do local _, y = data:row("val", i) sq = sq + (y[o] - mean) ^ 2 end
  var = var + sq / nval / 3
end

local function make() return sn.mlp { inputs = 6, hidden = {12, 12}, outputs = 3, seed = 4 } end
local a, b = make(), make()
local events = 0
local runs = sn.train { nets = { a, b }, data = data, epochs = 8, batch = 8, backend = "cpu", seed = 7,
                        adam = { lr = 3e-3, beta1 = 0.9, beta2 = 0.999 },
                        progress = function(e)
                          assert(e.net == 1 or e.net == 2, "progress net")
                          assert(e.val_mse > 0, "progress val_mse")
                          events = events + 1
                        end }
assert(events == 16, "progress events: " .. events)
assert(#runs == 2, "one result per net")
local r = runs[1]
assert(#r.train_mse == 8 and #r.val_mse == 8, "curves per epoch")
assert(r.best_val_mse < 0.05 * var, ("best %.3g vs constant predictor %.3g"):format(r.best_val_mse, var))
assert(r.val_mse[8] < r.val_mse[1], "loss goes down")
assert(r.val_mse[r.best_epoch] == r.best_val_mse, "best epoch points at best mse")
for e = 1, 8 do assert(r.best_val_mse <= r.val_mse[e], "best is the minimum") end
assert(r.diverged == nil, "not diverged")
assert(r.steps == 8 * 300, "steps " .. r.steps)  -- 2400 rows / batch 8 per epoch
assert(r.backend == "cpu" and r.device:find("kernel"), "backend " .. r.backend .. ", device " .. r.device)
assert(r.wall_time > 0 and r.sample_steps_per_s > 0, "timing")
assert(#r.dead_units == 2 and r.dead_units[1] >= 0 and r.dead_units[1] <= 1, "dead units per hidden layer")
-- Same seed, same init: identical curves and weights.
for e = 1, 8 do assert(runs[1].val_mse[e] == runs[2].val_mse[e], "deterministic epoch " .. e) end
assert(a.layers[2].weight[5][7] == b.layers[2].weight[5][7], "deterministic weights")
-- Committed: counters, version, names; the net now predicts well.
assert(a:trained_steps() == 8 * 300, "trained steps " .. a:trained_steps())
assert(a:version() > 1, "training bumps the version")
assert(table.concat(a:inputs(), ",") == "normal,view", "input names from the dataset")
local best = a:best()
assert(best.epoch == r.best_epoch and best.val_mse == r.best_val_mse, "net:best()")

-- keep = "best" leaves the best-epoch weights in the net; restore_best() does it afterwards.
local c, d = make(), make()
sn.train { nets = { c }, data = data, epochs = 8, backend = "cpu", seed = 7, keep = "best",
           adam = { lr = 3e-3, beta1 = 0.9, beta2 = 0.999 } }
sn.train { nets = { d }, data = data, epochs = 8, backend = "cpu", seed = 7,
           adam = { lr = 3e-3, beta1 = 0.9, beta2 = 0.999 } }
assert(d:restore_best(), "restore_best")
assert(c.layers[1].weight[3][2] == d.layers[1].weight[3][2], "keep best == restore_best")

-- A network of dead ReLUs is reported as such.
local dead = sn.mlp { inputs = 6, hidden = {8, 8}, outputs = 3, activation = "relu", init = "he", seed = 1 }
local biases = {}
for i = 1, 8 do biases[i] = -50 end
dead.layers[1].bias = biases
local rd = sn.train { nets = dead, data = data, epochs = 1, backend = "cpu" }
assert(rd[1].dead_units[1] == 1 and rd[1].dead_units[2] == 1, "dead relu layers")
assert(rd[1].best_val_mse > 0.9 * var, "a dead net cannot beat the constant predictor")

-- Divergence: outputs of 1e20 overflow the squared error; the net stops, others go on.
local blow = make()
blow.layers[3].bias = { 1e20, 1e20, 1e20 }
local ok_net = make()
local rv = sn.train { nets = { blow, ok_net }, data = data, epochs = 2, backend = "cpu" }
assert(rv[1].diverged and rv[1].diverged.epoch == 1 and rv[1].diverged.step == 1, "diverged at 1/1")
assert(math.abs(blow.layers[3].bias[1] / 1e20 - 1) < 1e-6, "diverged net keeps its last finite weights")
assert(rv[2].diverged == nil and #rv[2].val_mse == 2, "the other net trained")

-- A buffer works as rows too.
local flat_x, flat_y = {}, {}
for i = 1, 64 do for k = 1, 6 do flat_x[#flat_x + 1] = xs[i][k] end for k = 1, 3 do flat_y[#flat_y + 1] = ys[i][k] end end
local bx = sn.buffer { type = "float32", data = flat_x }
local by = sn.buffer { type = "float32", data = flat_y }
local bd = sn.dataset { x = bx, inputs = 6, y = by, outputs = 3, split = 0.75 }
local n1, n2 = bd:counts()
assert(n1 == 48 and n2 == 16, "buffer dataset split")
assert(table.concat(sn.backends(), ","):find("cpu"), "backends lists cpu")
-- "auto" takes the cpu backend on a software renderer (llvmpipe), gl on a hardware GPU.
local auto = sn.train { nets = make(), data = data, epochs = 1 }[1]
local expect = (sn.gl_info().software or not table.concat(sn.backends(), ","):find("gl")) and "cpu" or "gl"
assert(auto.backend == expect, "auto chose " .. auto.backend .. ", expected " .. expect)
-- In a progress function the net holds the parameters of the epoch just ended (the same as a
-- job of that many epochs gives it), on each backend; an edit made there is replaced by what was
-- trained, and the net cannot be trained by a second job meanwhile.
for _, backend in ipairs(sn.backends()) do
  local net = make()
  local start = net:clone()
  local seen, nested = {}, nil
  sn.train { nets = { net }, data = data, epochs = 3, backend = backend, progress = function(e)
    seen[e.epoch] = net:params()
    if e.epoch == 1 then
      net.layers[1].bias[1] = 50
      local ok, err = pcall(sn.train, { nets = { net }, data = data, epochs = 1, backend = backend })
      nested = ok and "trained" or err
    end
  end }
  assert(tostring(nested):find("sn.train: net 1 is being trained by a job that has not ended", 1, true), tostring(nested))
  assert(net.layers[1].bias[1] ~= 50, backend .. ": the edit made in progress was replaced")
  local final = net:params()
  for epochs = 1, 3 do
    local alone = start:clone()
    sn.train { nets = { alone }, data = data, epochs = epochs, backend = backend }
    local want = epochs == 3 and final or alone:params()
    for i, v in ipairs(alone:params()) do
      assert(seen[epochs][i] == v and want[i] == v, ("%s: epoch %d, parameter %d: seen %.9g, trained alone %.9g"):format(
        backend, epochs, i, seen[epochs][i], v))
    end
  end
end
print("test_mlp_train ok")

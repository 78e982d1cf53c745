-- Stopping sn.train cleanly (docs/reliability.md, "Stopping training"): on every backend the
-- first Ctrl-C or a progress function's "stop" ends the job at the next step boundary and
-- returns what was trained, flagged `interrupted`, with keep = "best" | "last" honoured; an
-- error in progress keeps the trained weights too; the second Ctrl-C ends the process.
local sn = require "shadenet"
local expect = require "expect"
local C = require "script_check"

local xs, ys = require("smooth_rows")(1200)
local data = sn.dataset { x = xs, y = ys, split = 0.8, seed = 1 }
local steps = 120  -- 960 training rows, batch 8
local function make() return sn.mlp { inputs = 6, hidden = { 12, 12 }, outputs = 3, seed = 4 } end
local same = expect.same_params
local adam = { lr = 3e-3 }

for _, backend in ipairs(sn.backends()) do
  local function train(net, o)
    o.nets, o.data, o.backend, o.adam, o.batch = net, data, backend, adam, 8
    return sn.train(o)[1]
  end
  -- Two epochs run straight: what a run stopped after epoch 2 must equal.
  local ref_last, ref_best = make(), make()
  local two = train(ref_last, { epochs = 2 })
  train(ref_best, { epochs = 2, keep = "best" })

  -- progress returns "stop" after epoch 2 of 5.
  for _, keep in ipairs { "last", "best" } do
    local net, seen = make(), 0
    local r = train(net, { epochs = 5, keep = keep, progress = function(e)
      seen = seen + 1
      if e.epoch == 2 then return "stop" end
    end })
    assert(seen == 2, backend .. ": progress heard 2 epochs, got " .. seen)
    assert(r.interrupted and r.interrupted.epoch == 2 and r.interrupted.step == steps,
           backend .. ": interrupted after epoch 2's last step")
    assert(r.epochs == 2 and #r.val_mse == 2 and r.steps == 2 * steps and net:trained_steps() == 2 * steps,
           backend .. ": two epochs kept")
    assert(r.val_mse[2] == two.val_mse[2], backend .. ": the stopped run is the two-epoch run")
    assert(same(net, keep == "best" and ref_best or ref_last), backend .. ": keep = " .. keep .. " honoured")
    assert(r.diverged == nil)
  end

  -- Any other return value is an error, and like any error in progress it keeps what was
  -- trained (the weights after epoch 1), then is raised.
  local net = make()
  local ok, err = pcall(train, net, { epochs = 5, progress = function() return true end })
  assert(not ok and err:find("the progress function returned boolean; return \"stop\" to end training, or nothing to go on", 1, true),
         backend .. ": " .. tostring(err))
  assert(net:trained_steps() == steps, backend .. ": an error keeps the epoch trained: " .. net:trained_steps())
  local one = make()
  train(one, { epochs = 1 })
  assert(same(net, one), backend .. ": the weights after epoch 1")
  net = make()
  ok, err = pcall(train, net, { epochs = 5, progress = function(e) if e.epoch == 3 then error("enough") end end })
  assert(not ok and err:find("the progress function failed: .*enough"), tostring(err))
  assert(net:trained_steps() == 3 * steps, backend .. ": three epochs kept after the error")

  -- Ctrl-C from outside, part-way through a long epoch, then saving the net (in a child).
  local tmp = C.tmpdir("stop")
  local code, out = C.run("tests/lua/train_interrupt_child.lua", { backend, "once", tmp .. "/net.snmlp" })
  assert(code == 0 and out:find("OK epoch"), backend .. ": one Ctrl-C (" .. tostring(code) .. "):\n" .. out)
  assert(out:find("interrupt: stopping training at the next step (Ctrl-C again to stop now)", 1, true), out)
  assert(sn.load(tmp .. "/net.snmlp"):trained_steps() > 0, "the saved net")
  print(backend .. ": " .. out:match("OK[^\n]*"))
  code, out = C.run("tests/lua/train_interrupt_child.lua", { backend, "twice", tmp .. "/net2.snmlp" })
  assert(code == 130 and not out:find("SURVIVED"), backend .. ": the second Ctrl-C ends the process (" ..
         tostring(code) .. "):\n" .. out)
  code, out = C.run("tests/lua/train_interrupt_child.lua", { backend, "before", tmp .. "/net3.snmlp" })
  assert(code == 130 and out:find("OK before") and not out:find("SURVIVED"),
         backend .. ": a Ctrl-C before sn.train stops it at once, the next ends the process (" .. tostring(code) .. "):\n" .. out)
  print(backend .. ": " .. out:match("OK before[^\n]*"))
  C.rm(tmp)
end
print("train stop: ok")

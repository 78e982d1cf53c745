-- sn.train's tick: called on the script's thread about every tick_seconds while an epoch runs
-- (what keeps a live window drawing during long epochs). On every backend it sees the epoch's
-- steps advance, it never changes what is trained, and it stops the job like progress does:
-- "stop" ends it at the next step boundary, an error keeps what was trained and is raised.
local sn = require "shadenet"
local expect = require "expect"

local data = sn.dataset.sample { target = sn.lighting.phong {}, n = 200000, seed = 3 }
local steps = 20000  -- 160,000 training rows, batch 8
local function make() return sn.mlp { inputs = 6, hidden = { 32, 32, 32 }, outputs = 3, seed = 5 } end
local same = expect.same_params

for _, backend in ipairs(sn.backends()) do
  local function train(net, o)
    o.nets, o.data, o.backend, o.batch, o.adam = net, data, backend, 8, { lr = 1e-3 }
    return sn.train(o)[1]
  end
  local plain = make()
  local t0 = sn.clock()
  train(plain, { epochs = 2 })
  local seconds = sn.clock() - t0
  local every = math.max(seconds / 40, 0.002)  -- about 20 ticks an epoch

  -- Ticks during both epochs, steps rising within each, the same weights as without ticks.
  local net, ticks = make(), {}
  train(net, { epochs = 2, tick_seconds = every, tick = function(t) ticks[#ticks + 1] = t end })
  assert(same(net, plain), backend .. ": a tick changes nothing that is trained")
  assert(#ticks >= 10, ("%s: %d ticks in %.3f s at one per %.4f s"):format(backend, #ticks, seconds, every))
  local within, last = 0, { epoch = 1, step = 0, fraction = 0 }
  for i, t in ipairs(ticks) do
    assert(t.epochs == 2 and t.steps == steps, backend .. ": the job's shape")
    assert(t.epoch == 1 or t.epoch == 2, backend .. ": epoch " .. t.epoch)
    assert(t.step >= 0 and t.step <= steps, backend .. ": step " .. t.step)
    assert(t.epoch > last.epoch or t.step >= last.step, ("%s: tick %d went back"):format(backend, i))
    assert(math.abs(t.fraction - ((t.epoch - 1) * steps + t.step) / (2 * steps)) < 1e-12, backend .. ": fraction")
    assert(t.fraction >= last.fraction, backend .. ": the fraction rises")
    if t.step > 0 and t.step < steps then within = within + 1 end
    last = t
  end
  assert(within >= 5, ("%s: %d of %d ticks fell inside an epoch"):format(backend, within, #ticks))

  -- "stop" from a tick part-way through the first epoch: interrupted there, steps kept.
  net = make()
  local seen = 0
  local r = train(net, { epochs = 2, tick_seconds = every, tick = function(t)
    seen = seen + 1
    if t.step > 0 then return "stop" end
  end })
  assert(r.interrupted and r.interrupted.epoch == 1 and r.interrupted.step > 0 and r.interrupted.step < steps,
         backend .. ": interrupted within epoch 1, got " .. tostring(r.interrupted and r.interrupted.step))
  assert(r.epochs == 0 and net:trained_steps() == r.steps and r.steps == r.interrupted.step,
         backend .. ": the steps applied are kept")

  -- An error in a tick stops the job, keeps what was trained, then is raised.
  net = make()
  local ok, err = pcall(train, net, { epochs = 2, tick_seconds = every, tick = function(t)
    if t.step > 0 then error("enough") end
  end })
  assert(not ok and err:find("sn.train: the tick function failed: .*enough"), backend .. ": " .. tostring(err))
  assert(net:trained_steps() > 0 and net:trained_steps() < 2 * steps, backend .. ": the steps before the error are kept")
  ok, err = pcall(train, make(), { epochs = 1, tick_seconds = every, tick = function() return 1 end })
  assert(not ok and err:find("the tick function returned number; return \"stop\" to end training, or nothing to go on",
                             1, true), tostring(err))
  -- Epochs shorter than the period: the beat carries over, so ticks still come.
  local small = sn.dataset.sample { target = sn.lighting.phong {}, n = 2000, seed = 4 }
  local short = {}
  t0 = sn.clock()
  sn.train { nets = make(), data = small, epochs = 60, backend = backend, tick_seconds = 0.004,
             tick = function(t) short[#short + 1] = t end }
  local short_seconds = sn.clock() - t0
  assert(#short >= short_seconds / 0.004 / 4 and #short >= 3,
         ("%s: %d ticks in %.3f s of 60 short epochs"):format(backend, #short, short_seconds))
  print(("%s: %d ticks in 2 epochs of %d steps (%.3f s), %d inside an epoch; stop at step %d"):format(
    backend, #ticks, steps, seconds, within, r.interrupted.step) ..
    ("; %d ticks in 60 epochs of 200 steps (%.3f s)"):format(#short, short_seconds))
end

-- Options people get wrong.
local function fails(o, pattern)
  o.nets, o.data = make(), data
  local ok, err = pcall(sn.train, o)
  assert(not ok and err:find(pattern, 1, true), tostring(err))
end
fails({ tick_seconds = 0.1 }, "sn.train option 'tick_seconds' needs a tick function (option 'tick')")
fails({ tick = function() end, tick_seconds = 0 }, "tick_seconds must be in (0, 3600], got 0")
fails({ tick = "often" }, "sn.train option 'tick': function expected, got string")
print("train tick: ok")

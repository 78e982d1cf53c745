-- Run by tests/lua/test_train_stop.lua in a child shadenet: trains one network for a long epoch
-- on `backend` and has SIGINT sent to it a second in, as a terminal's Ctrl-C is (from another
-- process, so the signal lands while the training threads or the GPU work).
--   mode "once":  one Ctrl-C; checks the result is flagged and the net kept and saved to `out`,
--                 and that a later sn.train trains,
--                 prints "OK ...".
--   mode "twice": two Ctrl-Cs; the second must end the process (exit status 130), so reaching
--                 the end prints "SURVIVED".
--   mode "before": under sn.catch_interrupt(), a Ctrl-C before sn.train begins (a sweep building
--                 its dataset): the training stops at once, prints "OK before ...", and the next
--                 Ctrl-C ends the process (130; it trained the whole group, and caught the next).
local sn = require "shadenet"
local ffi = require "ffi"
ffi.cdef [[
int getpid(void);
typedef void (*sn_sighandler_t)(int);
sn_sighandler_t signal(int sig, sn_sighandler_t handler);
]]
local backend, mode, out = arg[1], arg[2], arg[3]
-- A shell starts a background job with SIGINT ignored (and sn.train leaves an ignored SIGINT
-- alone); a terminal's foreground job has the default action, as here.
ffi.C.signal(2, ffi.cast("sn_sighandler_t", 0))

local big = backend == "cpu" and { 64, 64, 64, 64 } or { 16, 16 }
local batch = backend == "cpu" and 1 or 8
local data = sn.dataset.sample { target = sn.lighting.phong {}, n = 400000, seed = 3, split = 0.95 }
local function make() return sn.mlp { inputs = 6, hidden = big, outputs = 3, seed = 5 } end
-- A warm-up on a few rows compiles the gl programs, so the timed run starts training at once.
local small = data:subset { count = 80 }
local w0 = sn.clock()
sn.train { nets = make(), data = small, epochs = 1, batch = batch, backend = backend }
-- The Ctrl-C comes well after training has begun, however slow this build (a sanitizer's).
local delay = math.max(1.0, 3 * (sn.clock() - w0))

local net = make()
local before = net:params()
local steps_per_epoch = math.floor(select(1, data:counts()) / batch)
if mode == "before" then
  sn.catch_interrupt()
  -- From a background shell, a moment later: system() ignores SIGINT until its child has ended.
  os.execute(string.format("(sleep 0.2; kill -INT %d) &", ffi.C.getpid()))
  local w = sn.clock()
  while not sn.interrupted() and sn.clock() - w < 20 do end
  assert(sn.interrupted(), "the Ctrl-C arrived")
  local t0 = sn.clock()
  local r = sn.train { nets = net, data = data, epochs = 100, batch = batch, backend = backend }[1]
  local seconds = sn.clock() - t0
  assert(r.interrupted and r.steps == 0 and net:trained_steps() == 0, "stopped before its first step: " .. r.steps)
  for i, v in ipairs(net:params()) do assert(v == before[i], "the weights as they were") end
  print(string.format("OK before: stopped in %.2f s", seconds))
  io.stdout:flush()
  os.execute(string.format("(sleep 0.2; kill -INT %d) &", ffi.C.getpid()))
  local t1 = sn.clock()
  while sn.clock() - t1 < 20 do end
  print("SURVIVED")
  os.exit(0)
end
-- (Two signals sent at once would merge into one pending signal; a person's second Ctrl-C
-- comes later.)
local kills = mode == "twice" and "kill -INT %d; sleep 0.3; kill -INT %d" or "kill -INT %d"
os.execute(string.format("(sleep %.2f; " .. kills .. ") &", delay, ffi.C.getpid(), ffi.C.getpid()))
local t0 = sn.clock()
local r = sn.train { nets = net, data = data, epochs = 100, batch = batch, backend = backend, keep = "best" }[1]
local seconds = sn.clock() - t0
if mode == "twice" then
  -- Ctrl-C's default action is back: the second one ends the process, here at the latest.
  while sn.clock() - t0 < 20 do end
  print("SURVIVED")
  os.exit(0)
end

local stop = r.interrupted
assert(stop, "the result is flagged interrupted")
assert(stop.epoch >= 1 and stop.step >= 1 and stop.step <= steps_per_epoch, "stopped at a step: " .. stop.epoch .. "/" .. stop.step)
assert(r.steps == (stop.epoch - 1) * steps_per_epoch + stop.step, "steps " .. r.steps .. " = where it stopped")
assert(#r.val_mse == stop.epoch - (stop.step == steps_per_epoch and 0 or 1), "curves of the finished epochs only")
-- The first epoch is seconds long on a CPU or a software renderer: the stop came part-way through it.
if #r.val_mse == 0 then assert(stop.epoch == 1 and stop.step < steps_per_epoch, "stopped inside the epoch") end
assert(r.diverged == nil, "not diverged")
assert(sn.interrupted(), "sn.interrupted() saw the Ctrl-C")
assert(net:trained_steps() == r.steps, "the net keeps its steps: " .. net:trained_steps())
-- keep = "best" with no finished epoch keeps the last weights; with finished ones, the best.
local changed = false
for i, v in ipairs(net:params()) do changed = changed or v ~= before[i] end
assert(changed, "the net keeps what was trained")
net:save(out)
local back = sn.load(out)
assert(back:trained_steps() == r.steps, "saved and loaded")
-- Without sn.catch_interrupt() a past Ctrl-C stopped that training only: a later one trains
-- (in live mode every later training ran 0 steps, and sn.keep kept untrained networks).
local later = make()
sn.train { nets = later, data = small, epochs = 1, batch = batch, backend = backend }
assert(later:trained_steps() > 0, "a later training after the Ctrl-C trains: " .. later:trained_steps())
print(string.format("OK epoch %d step %d of %d, %d epochs finished, %.2f s", stop.epoch, stop.step, steps_per_epoch,
                    #r.val_mse, seconds))

-- What it costs that Esc and Ctrl-C can stop a live run (runtime/live/run_guard.h: a count hook
-- every 10,000 instructions and LuaJIT's profiler every 10 ms of CPU time, whose exit checks are
-- compiled into every trace): the same Lua workloads timed inside a script run plainly (no
-- guard) and run by `shadenet --watch` headless (guarded), alternately, `repeats` times each, in
-- CPU seconds of the process (os.clock).
--
--   shadenet bench/live_interrupt.lua [repeats] [other_shadenet]
--     repeats: runs of each kind (default 5)
--     other_shadenet: also time the --watch runs of another build (e.g. the one before the guard)
--
-- Workloads: a numeric loop (compiled by the JIT), tables made in a loop (compiled, allocating),
-- tostring (a builtin the JIT compiles), a Lua function called through a table of closures, and
-- reads of a network's weights through the bindings (C functions: interpreted). Prints the
-- median CPU seconds of each and the guarded run's time relative to the plain one, and the 1-minute
-- load average.
local sn = require "shadenet"
package.path = (arg[0]:match("^(.*)/[^/]*$") or ".") .. "/?.lua;" .. package.path
local B = require "common"

local any = { form = "a path to a shadenet binary", parse = function(s) return s end }
local o = B.args("bench/live_interrupt.lua", { { "repeats", "5", B.whole(1) }, { "other_shadenet", "", any } })
local other = o.other_shadenet ~= "" and o.other_shadenet or nil
local dir = "out/bench/live_interrupt"
sn.fs.mkdir(dir)
local workload = dir .. "/workload.lua"
local f = assert(io.open(workload, "w"))
f:write([[
local sn = require "shadenet"
local function time(name, fn)
  fn(1)  -- once small: the JIT's warm-up is not what is measured
  local t0 = os.clock()  -- CPU time: a loaded machine's other processes count less than in wall time
  fn(0)
  io.stderr:write(("T %s %.6f\n"):format(name, os.clock() - t0))
end
time("numeric loop", function(s) local x = 0 for i = 1, s > 0 and 1e5 or 6e7 do x = x + i % 7 end return x end)
time("tables", function(s) local t = {} for i = 1, s > 0 and 1e4 or 3e6 do t[i % 1000 + 1] = { i, i + 1 } end end)
time("tostring", function(s) local n = 0 for i = 1, s > 0 and 1e4 or 2e6 do n = n + #tostring(i) end end)
local fns = {}
for k = 1, 8 do fns[k] = function(x) return x * k + 1 end end
time("closure calls", function(s) local x = 0 for i = 1, s > 0 and 1e4 or 2e7 do x = fns[i % 8 + 1](x) % 1000 end end)
local net = sn.mlp { inputs = 6, hidden = { 16 }, outputs = 3, seed = 1 }
local w = net.layers[1].weight
time("weight reads", function(s) local x = 0 for i = 1, s > 0 and 1e3 or 3e5 do x = x + w[i % 16 + 1][i % 6 + 1] end end)
if sn.live.active() then sn.live.quit() end  -- the session ends after this run
]])
f:close()

local function run(binary, live)
  local cmd = live and ("SHADENET_LIVE_EXIT_AFTER=600 %q --watch %q < /dev/null 2>&1"):format(binary, workload)
              or ("%q %q 2>&1"):format(binary, workload)
  local p = io.popen(cmd)
  local out = p:read("*a")
  p:close()
  local t = {}
  for name, secs in out:gmatch("T ([^\n]-) (%d+%.%d+)\n") do t[name] = tonumber(secs) end
  assert(next(t), "the workload printed no times: " .. cmd .. "\n" .. out)
  return t
end

local kinds = { { "plain", binary = arg[-1], live = false }, { "--watch", binary = arg[-1], live = true } }
if other then kinds[#kinds + 1] = { "--watch (" .. other .. ")", binary = other, live = true } end
local times = {}
for _ = 1, o.repeats do
  for _, k in ipairs(kinds) do
    for name, secs in pairs(run(k.binary, k.live)) do
      times[k[1]] = times[k[1]] or {}
      times[k[1]][name] = times[k[1]][name] or {}
      table.insert(times[k[1]][name], secs)
    end
  end
end
local names = { "numeric loop", "tables", "tostring", "closure calls", "weight reads" }
print(("median of %d runs each, CPU seconds (relative to plain)"):format(o.repeats))
for _, name in ipairs(names) do
  local plain = B.median(times.plain[name])
  local line = ("%-14s plain %.3f"):format(name, plain)
  for i = 2, #kinds do
    local m = B.median(times[kinds[i][1]][name])
    line = line .. ("   %s %.3f (%+.1f%%)"):format(kinds[i][1], m, 100 * (m / plain - 1))
  end
  print(line)
end
print("load average " .. B.load())

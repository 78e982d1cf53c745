-- The benchmarks (bench/) on tiny settings: their options are checked before any work, the
-- columns of train_throughput span what its header says, the roofline counts the trainer's
-- threads, fma_peak is found through PATH, and Ctrl-C stops a benchmark (exit 130) without
-- printing the cut-short job or leaving its scratch folder.
local sn = require "shadenet"
local C = require "script_check"

local function sh_quote(s) return "'" .. tostring(s):gsub("'", "'\\''") .. "'" end

-- Bad options: exit 2 before any work, the message naming the option and what it takes.
local bad = {
  { "bench/train_throughput.lua", { "cpu", "-2" }, "counts '%-2': expected a whole number >= 1; one or more, comma separated" },
  { "bench/train_throughput.lua", { "cpu", "1,0" }, "counts '1,0'" },
  { "bench/train_throughput.lua", { "cpu", "1", "abc" }, "epochs 'abc': expected a whole number >= 1" },
  { "bench/train_throughput.lua", { "cpu", "1", "1", "tanh", "8-8" }, "archs '8%-8': expected LAYERSxWIDTH" },
  { "bench/train_throughput.lua", { "cpu", "1", "1", "tanhh" }, "activations 'tanhh': expected one of all, tanh," },
  { "bench/train_throughput.lua", { "cpu", "1", "1", "tanh", "2x2", "frequency:0" }, "encodings 'frequency:0'" },
  { "bench/train_throughput.lua", { "tpu" }, "backend 'tpu': expected one of cpu, gl, all" },
  { "bench/train_throughput.lua", { "cpu", "1", "1", "tanh", "2x2", "none", "x" }, "7 arguments given, it takes at most 6" },
  { "bench/render_throughput.lua", { "0" }, "repeats '0': expected a whole number >= 1" },
  { "bench/render_throughput.lua", { "-1" }, "repeats '%-1'" },
  { "bench/render_throughput.lua", { "1", "gl", "auto", "4-4" }, "archs '4%-4'" },
  { "bench/render_throughput.lua", { "1", "cpu", "bogus" }, "weights 'bogus': expected one of auto, storage" },
  { "bench/render_throughput.lua", { "1", "cpu", "storage" }, "weights 'storage' is for the gl backend" },
  { "bench/render_throughput.lua", { "1", "cpu", "auto", "4x4", "640" }, "sizes '640': expected WIDTHxHEIGHT" },
  { "bench/live_view.lua", { "cpu", "0" }, "frames '0': expected a whole number >= 1" },
  { "bench/live_view.lua", { "cpu", "1", "8x8", "sides" }, "mode 'sides': expected one of network, side, error" },
  { "bench/sweep_steps.lua", { "0" }, "repeats '0'" },
  { "bench/sweep_steps.lua", { "1", "0" }, "seeds '0'" },
  { "bench/dataset_ops.lua", { "0" }, "repeats '0'" },
  { "bench/dataset_ops.lua", { "1", "README.md" }, "dir 'README.md': expected a folder to write into" },
  { "bench/encoding_twin.lua", { "0" }, "repeats '0'" },
}
for _, b in ipairs(bad) do
  local script, args, want = b[1], b[2], b[3]
  local code, out = C.run(script, args)
  local what = script .. " " .. table.concat(args, " ")
  assert(code == 2, what .. ": exit " .. tostring(code) .. ", expected 2:\n" .. out)
  assert(out:find(script .. ": " .. want), what .. ": expected '" .. want .. "' in:\n" .. out)
  assert(out:find("(usage: shadenet " .. script .. " [", 1, true) and not out:find("traceback"), what .. ":\n" .. out)
end

-- fma_peak: seconds outside 0.01..60 (1e-9 timed one iteration: 0.0 GFLOP/s) or not a number.
local build = C.shadenet:match("^(.*)/[^/]*$") or "."
for _, s in ipairs { "1e-9", "abc", "0.05x", "61" } do
  local out = C.output(sh_quote(build .. "/fma_peak") .. " " .. s .. " 2>&1; echo \"exit $?\"")
  assert(out:find("fma_peak: seconds '" .. s .. "': expected seconds per measurement, 0.01 to 60", 1, true)
         and out:find("exit 2\n", 1, true), s .. ":\n" .. out)
end

-- fma_peak beside a shadenet found through PATH (arg[-1] is then a bare name), from a script
-- outside the repository.
local cwd = C.output("pwd"):match("^(.-)%s*$")
local child = C.child("bench_path", [[
package.path = ]] .. ("%q"):format(cwd .. "/bench/?.lua;") .. [[ .. package.path
local R = require "roofline"
print("arg[-1]=" .. tostring(arg[-1]))
print("path=" .. tostring(R.fma_peak_path()))
]])
local out = C.output("PATH=" .. sh_quote(build) .. ":\"$PATH\" shadenet " .. sh_quote(child))
local real = C.output("readlink -f " .. sh_quote(build .. "/fma_peak")):match("^(.-)%s*$")
local found = out:match("path=(%S+)")
assert(out:find("arg[-1]=shadenet\n", 1, true) and found and
       C.output("readlink -f " .. sh_quote(found)):match("^(.-)%s*$") == real, "fma_peak through PATH:\n" .. out)

-- train_throughput through a wrapper: a stand-in FMA peak (100 GFLOP/s per core, 2 threads:
-- fma_peak itself takes seconds), and sn.train wrapped by `wrap`.
local function throughput(tag, wrap, args, env)
  local wrapper = C.tmpdir(tag) .. "/wrapper.lua"
  sn.fs.write(wrapper, [[
local sn = require "shadenet"
local ffi = require "ffi"
ffi.cdef "int getpid(void); int kill(int pid, int sig);"
local R = dofile("bench/roofline.lua")
R.measure_peak = function() return { avx2 = { core = 100, all = 200 }, threads = 2 } end
package.loaded.roofline = R
local train = sn.train
]] .. wrap .. [[
arg[0] = "bench/train_throughput.lua"
dofile(arg[0])
]])
  return C.run(wrapper, args, env)
end
-- The row of a job: its columns by name.
local columns = { "backend", "arch", "activation", "encoding", "inputs", "nets", "total", "per_net", "train", "wall",
                  "cpu", "per_cpu", "load", "peak", "flop", "gflops", "avx2", "avx512" }
local function rows(out)
  local list = {}
  for line in out:gmatch("[^\n]+") do
    if line:match("^cpu +%d+x%d+ ") then
      local r, i = {}, 0
      for cell in line:gmatch("%S+") do
        i = i + 1
        r[columns[i]] = tonumber(cell) or cell
      end
      list[#list + 1] = r
    end
  end
  return list
end

-- wall s and cpu s span the same call: 0.3 s of CPU burnt inside it before the training is in
-- both, not in train s (the training's own time, whose rate is printed). One thread, so the
-- CPU time cannot exceed the wall time. The roofline holds 2 networks on 1 thread against one
-- core's peak: %avx2 = GFLOP/s (100 per core).
local code, out = throughput("bench_span", [[
sn.train = function(o)
  local c = os.clock()
  while os.clock() - c < 0.3 do end
  return train(o)
end
]], { "cpu", "2", "1", "tanh", "2x2" }, { SHADENET_THREADS = "1" })
assert(code == 0, out)
assert(out:find(" train s +wall s +cpu s "), out)
local r = rows(out)[1]
assert(r and r.nets == 2 and r.wall >= 0.3 and r.train < r.wall - 0.25 and r.cpu <= r.wall + 0.02, "spans:\n" .. out)
assert(math.abs(r.avx2 - r.gflops) <= 0.06, "2 nets on SHADENET_THREADS=1 against one core's peak:\n" .. out)
assert(out:find("\ncpu: .*, 1 threads, "), out)

-- Ctrl-C inside a job (after its first epoch of 2): the job is not printed, nor the next; exit 130.
code, out = throughput("bench_interrupt", [[
sn.train = function(o)
  o.progress = function() ffi.C.kill(ffi.C.getpid(), 2) end  -- SIGINT, as a terminal's Ctrl-C
  return train(o)
end
]], { "cpu", "1,2", "2", "tanh", "2x2" })
assert(code == 130, "exit " .. tostring(code) .. ":\n" .. out)
assert(#rows(out) == 0 and out:find("\nstopped %(Ctrl%-C%): the job cpu 2x2 tanh none, 1 nets %(cut short%) is not printed\n"),
       out)

-- Ctrl-C once a benchmark's scratch folder exists: it stops (130) and the folder goes with it
-- (SIGINT's default action left it in TMPDIR).
for _, b in ipairs { { "bench/sweep_steps.lua", "sweep_steps" }, { "bench/dataset_ops.lua", "dataset_ops" } } do
  local dir = C.tmpdir("bench_tmp")
  local wrapper = dir .. "/wrapper.lua"
  sn.fs.mkdir(dir .. "/tmp")
  sn.fs.write(wrapper, ([[
local sn = require "shadenet"
local ffi = require "ffi"
ffi.cdef "int getpid(void); int kill(int pid, int sig);"
local tempdir = sn.fs.tempdir
sn.fs.tempdir = function(tag)
  local d = tempdir(tag)
  ffi.C.kill(ffi.C.getpid(), 2)
  return d
end
arg[0] = %q
dofile(arg[0])
]]):format(b[1]))
  code, out = C.run(wrapper, { "1" }, { TMPDIR = dir .. "/tmp" })
  assert(code == 130 and out:find("\nstopped %(Ctrl%-C%)"), b[1] .. ": exit " .. tostring(code) .. ":\n" .. out)
  local left = sn.fs.list(dir .. "/tmp")
  assert(#left == 0, b[1] .. " left " .. table.concat(left, ", ") .. " in TMPDIR")
end
print("ok")

-- Training throughput: sample-steps per second (one sample through forward, backward and its
-- share of the Adam step) for the thesis' architectures, with 1 .. 360 networks per job.
--
--   shadenet bench/train_throughput.lua [backend] [counts] [epochs] [activations] [archs] [encodings]
--     backend:     cpu | gl | all (default: every backend in this build)
--     counts:      networks per job, comma separated (default 1,2,8,32,360)
--     epochs:      epochs per job (default 1)
--     activations: hidden activations, comma separated (default tanh; "all": every built-in;
--                  "tanh_defined" and "softsign": definitions as a script makes them, whose
--                  GLSL the cpu backend runs translated)
--     archs:       hidden layers x width, comma separated (default 4x6,8x8,8x12,12x12)
--     encodings:   input encodings, comma separated (default none): none, or NAME:N, the encoding
--                  NAME (frequency, oneblob, sh, triangle_wave) with count N (bands, bins or
--                  degree) on both input groups
--
-- Synthetic data: 64,000 samples of 6 inputs (named normal, view: two groups of 3) -> 3
-- outputs, split 80/20 (51,200 training rows), batch 8, Adam. "total steps/s" and "per net" are
-- the training's rate: sample-steps over "train s", sn.train's own wall_time (the epochs with
-- their per-epoch validation passes). "wall s" and "cpu s" both span the whole sn.train call,
-- which adds the untrained networks' validation MSE before the training and the dead-unit and
-- stuck-output passes after it: wall clock, and the process CPU time (all threads);
-- "steps/cpu-s" the sample-steps per CPU-second of that call; "load" the 1-minute load average
-- before the job: other work on the machine slows the wall-clock figures, hardly the CPU-time
-- ones.
--
-- The roofline (cpu backend): "FLOP/step" counted from the kernel per sample-step
-- (bench/roofline.lua), "GFLOP/s" achieved (total steps/s x FLOP/step), and that as a share of
-- this machine's measured FP32 FMA peak (build/fma_peak) over the cores the job can use (one
-- per network, at most the trainer's threads: SHADENET_THREADS, else the machine's): "%avx2"
-- against the AVX2 peak, "%avx512" against the AVX-512 one. The last lines name each backend's
-- device (the cpu backend's threads and kernel: avx512, avx2 or sse2; SHADENET_CPU_KERNEL picks
-- one) and the gl backend's training kernel (SHADENET_GL_KERNEL=per_sample|per_net forces one).
--
-- Ctrl-C stops it after the job in flight, which is cut short and not printed; exit status 130.
local sn = require "shadenet"
package.path = (arg[0]:match("^(.*)/[^/]*$") or ".") .. "/?.lua;" .. package.path
local B = require "common"
local roofline = require "roofline"

-- sn.activation.define'd activations: tanh_defined is the built-in's arithmetic (mlp_tanh is the
-- cpu backend's fast_tanh), so that it prices the translation alone.
local defined = {
  tanh_defined = { glsl = "mlp_tanh(x)", grad = "vec4 t = mlp_tanh(x); return 1.0 - t * t;", lua = math.tanh,
                   lua_grad = function(x) return 1 - math.tanh(x) ^ 2 end },
  softsign = { glsl = "x / (1.0 + abs(x))", grad = "vec4 d = 1.0 + abs(x); return 1.0 / (d * d);",
               lua = function(x) return x / (1 + math.abs(x)) end, lua_grad = function(x) return 1 / (1 + math.abs(x)) ^ 2 end },
}
local all_activations = { "tanh", "sigmoid", "relu", "leaky_relu", "sine", "softplus", "squareplus", "elu", "gelu",
                          "swish", "exponential" }
local activation_names = { "all" }
for _, a in ipairs(all_activations) do activation_names[#activation_names + 1] = a end
activation_names[#activation_names + 1] = "tanh_defined"
activation_names[#activation_names + 1] = "softsign"
local count_of = { frequency = "bands", triangle_wave = "bands", oneblob = "bins", sh = "degree" }
local encoding = {
  form = "none or NAME:N, NAME one of frequency, oneblob, sh, triangle_wave and N a whole number >= 1",
  parse = function(e)
    if e == "none" then return { label = "none" } end
    local name, n = e:match("^([%w_]+):(%d+)$")
    if not (name and count_of[name] and tonumber(n) >= 1) then return nil end
    local one = { name, [count_of[name]] = tonumber(n) }
    return { label = e, encoding = { normal = one, view = one } }
  end,
}
local script = "bench/train_throughput.lua"
local specs = {
  { "backend", "all", B.one_of { "cpu", "gl", "all" } },
  { "counts", "1,2,8,32,360", B.list(B.whole(1)) },
  { "epochs", "1", B.whole(1) },
  { "activations", "tanh", B.list(B.one_of(activation_names)) },
  { "archs", "4x6,8x8,8x12,12x12", B.list(B.arch) },
  { "encodings", "none", B.list(encoding) },
}
local o = B.args(script, specs)
local backends = {}
for _, b in ipairs(sn.backends()) do
  if o.backend == "all" or o.backend == b then backends[#backends + 1] = b end
end
if #backends == 0 then
  B.fail(script, specs, "backend '" .. o.backend .. "' is not in this build (have: " .. table.concat(sn.backends(), ", ") .. ")")
end
local counts, epochs, archs, encodings = o.counts, o.epochs, o.archs, o.encodings
local activations = {}
for _, a in ipairs(o.activations) do
  if a == "all" then
    for _, b in ipairs(all_activations) do activations[#activations + 1] = b end
  else
    activations[#activations + 1] = a
  end
end
for _, a in ipairs(activations) do
  local d = defined[a]
  if d and not d.name then
    d.name = a
    sn.activation.define(d)
  end
end
B.catch_interrupt()
local function make_net(hidden, act, enc, seed)
  return sn.mlp { inputs = { "normal", "view" }, hidden = hidden, outputs = 3, activation = act, seed = seed,
                  encoding = enc.encoding }
end

local function status(field)
  local f = io.open("/proc/self/status")
  if not f then return 0 end
  local text = f:read("*a")
  f:close()
  return tonumber(text:match(field .. ":%s*(%d+)")) or 0
end
-- 64k samples of a smooth function (a stand-in for a lighting model), written straight into
-- float buffers (no Lua tables: they would dominate the peak memory).
local rows = 64000
local bx = sn.buffer { type = "float32", size = rows * 6 }
local by = sn.buffer { type = "float32", size = rows * 3 }
local px, py = bx:ffi(), by:ffi()
for i = 0, rows - 1 do
  for k = 1, 6 do px[i * 6 + k - 1] = math.sin(i * (k + 0.37) * 0.0173 + k) end
  local x1, x2, x3, x4, x5, x6 = px[i * 6], px[i * 6 + 1], px[i * 6 + 2], px[i * 6 + 3], px[i * 6 + 4], px[i * 6 + 5]
  py[i * 3] = 0.5 + 0.4 * x1 * x4
  py[i * 3 + 1] = 0.5 + 0.3 * math.sin(x2 + x5)
  py[i * 3 + 2] = 0.3 + 0.2 * x3 - 0.1 * x6
end
local data = sn.dataset { x = bx, inputs = 6, y = by, outputs = 3, split = 0.8, seed = 1, input_names = { "normal", "view" } }
bx:release()
by:release()

-- The gl backend compiles one program per architecture on its first use (seconds on llvmpipe):
-- a small job per architecture compiles it before anything is timed.
local wx, wy = {}, {}
for i = 1, 80 do wx[i] = { 0, 0, 0, 0, 0, i / 80 } wy[i] = { 0.5, 0.5, 0.5 } end
local warm = sn.dataset { x = wx, y = wy, input_names = { "normal", "view" } }

local jobs = {}  -- (architecture, activation, encoding), encodings innermost
for _, a in ipairs(archs) do
  for _, act in ipairs(activations) do
    for _, enc in ipairs(encodings) do jobs[#jobs + 1] = { a, act, enc } end
  end
end

local ntrain = data:counts()
print(("dataset: %d samples (%d training), %d epoch(s), batch 8"):format(rows, ntrain, epochs))
local peak, no_peak = roofline.measure_peak()
if peak then
  print(("FMA peak (build/fma_peak), GFLOP/s per core: avx2 %.1f, avx512 %s; %d threads"):format(peak.avx2.core,
    peak.avx512 and ("%.1f"):format(peak.avx512.core) or "-", peak.threads))
else
  print("no roofline fractions: " .. no_peak)
end
B.stop_if_interrupted()
print(("%-7s %-6s %-11s %-15s %6s %5s %14s %12s %8s %8s %8s %14s %6s %9s %9s %8s %6s %7s"):format("backend", "arch",
  "activation", "encoding", "inputs", "nets", "total steps/s", "per net", "train s", "wall s", "cpu s", "steps/cpu-s",
  "load", "peak MiB", "FLOP/step", "GFLOP/s", "%avx2", "%avx512"))
local devices = {}  -- what each backend ran on (the cpu backend names its threads and kernel)
for _, backend in ipairs(backends) do
  for _, job in ipairs(jobs) do
    local a, act, enc = job[1], job[2], job[3]
    local hidden = {}
    for i = 1, a[1] do hidden[i] = a[2] end
    local name = ("%s %dx%d %s %s"):format(backend, a[1], a[2], act, enc.label)
    if backend == "gl" then
      sn.train { nets = make_net(hidden, act, enc, 1), data = warm, epochs = 1, batch = 8, backend = "gl" }
      B.stop_if_interrupted("the warm-up of " .. name)
    end
    for _, count in ipairs(counts) do
      local nets = {}
      for s = 1, count do nets[s] = make_net(hidden, act, enc, s) end
      local load = B.load()
      -- Wall and CPU time over the same span, the whole call.
      local t0, c0 = sn.clock(), os.clock()
      local runs = sn.train { nets = nets, data = data, epochs = epochs, batch = 8, backend = backend,
                              adam = { lr = 2.5e-4, beta1 = 0.8, beta2 = 0.9 } }
      local cpu, call = os.clock() - c0, sn.clock() - t0
      -- A Ctrl-C stopped the training part-way: its figures would be of a shorter job.
      B.stop_if_interrupted(("the job %s, %d nets (cut short)"):format(name, count))
      devices[backend] = runs[1].device
      local steps = 0
      for _, r in ipairs(runs) do steps = steps + r.steps * 8 end
      local wall = runs[1].wall_time  -- the training's own span: its rate is the one reported
      local roof = { "-", "-", "-", "-" }
      if backend == "cpu" then
        local widths = { nets[1]:spec().encoded_inputs }
        for _, w in ipairs(hidden) do widths[#widths + 1] = w end
        widths[#widths + 1] = 3
        local flop = roofline.flop_per_sample_step(widths, act)
        local gflops = steps / wall * flop / 1e9
        roof = { ("%.0f"):format(flop), ("%.2f"):format(gflops), "-", "-" }
        if peak then
          local cores = roofline.cores(count, runs[1].device, peak.threads)
          roof[3] = ("%.1f"):format(100 * gflops / (peak.avx2.core * cores))
          if peak.avx512 then roof[4] = ("%.1f"):format(100 * gflops / (peak.avx512.core * cores)) end
        end
      end
      print(("%-7s %-6s %-11s %-15s %6d %5d %14.0f %12.0f %8.2f %8.2f %8.2f %14.0f %6s %9.1f %9s %8s %6s %7s"):format(
        backend, a[1] .. "x" .. a[2], act, enc.label, nets[1]:spec().encoded_inputs, count, steps / wall,
        steps / wall / count, wall, call, cpu, steps / cpu, load, status("VmHWM") / 1024, roof[1], roof[2], roof[3], roof[4]))
      nets, runs = nil, nil
      collectgarbage()
    end
  end
end
for _, backend in ipairs(backends) do
  if devices[backend] then print(("%s: %s"):format(backend, devices[backend])) end
end
if devices.gl then
  local forced = os.getenv("SHADENET_GL_KERNEL")
  local rule = sn.gl_info().software and "per_net for networks that fit it, else per_sample (a CPU renderer)"
               or "per_sample (a GPU)"
  print("gl kernel: " .. ((forced and forced ~= "" and forced ~= "auto") and forced .. " (SHADENET_GL_KERNEL)" or rule))
end
print(("peak resident memory (VmHWM): %.1f MiB"):format(status("VmHWM") / 1024))

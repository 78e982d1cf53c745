-- The roofline columns of bench/train_throughput.lua: how many FLOP one sample-step of the cpu
-- backend executes, and this machine's measured FMA peak (build/fma_peak) to hold them against.
--
-- FLOP are counted from the kernel as it runs (runtime/nn/cpu_net.cpp; a multiply-add is 2, a
-- division or square root 1, compares and selects 0), per sample of a minibatch of 8 (one
-- 8-lane block), for widths w[0] (the encoded inputs) .. w[L] (the outputs), l2 loss, linear
-- output:
--   forward     sum over layers of 2 w[l] w[l+1], and f(z) on every hidden unit
--   loss        4 per output (error, its square, the scaled gradient)
--   gradient    sum of 2 w[l+1] inpad[l] (inpad = w rounded up to 4: the outer products run
--               over the padded inputs), plus 1 per bias
--   backward    sum over l >= 1 of 2 w[l+1] w[l], plus per hidden unit 1 (times f'(z)) and
--               the cost of f'(z) where it is taken from f(z)
--   Adam        15 per padded parameter (the kernel updates every float of the padded copy),
--               shared by the 8 samples
-- For 8x8 tanh (6 -> 8x8 -> 3) that is 5,811 FLOP, 3,056 of them in the three matrix products.
-- The avx512 kernel's pair mode (two networks' blocks of 8 in 16 lanes) executes the same per
-- sample.
local R = {}

-- Per hidden unit: FLOP of f(z) in a training forward pass, and of f'(z) from f(z) in the
-- backward pass (0 where the forward pass keeps f'(z)), counted from runtime/nn/cpu_activation.h
-- (its exp 21, fast_tanh 21, sin-cos 24, log1p 17).
R.activation_flop = {
  tanh = { 21, 2 }, sigmoid = { 24, 2 }, relu = { 0, 0 }, leaky_relu = { 1, 0 }, sine = { 26, 0 },
  softplus = { 41, 0 }, squareplus = { 7, 3 }, elu = { 23, 1 }, gelu = { 38, 0 }, swish = { 28, 0 },
  exponential = { 21, 0 },
  -- bench/train_throughput.lua's defined activations, as their translated GLSL runs
  -- (runtime/nn/cpu_expr.h): the forward pass computes f(z) and f'(z) in one program, the steps
  -- they share once.
  tanh_defined = { 23, 0 }, softsign = { 4, 0 },
}

local function round_up(n, m) return math.ceil(n / m) * m end

-- FLOP per sample-step and the share of the three matrix products.
function R.flop_per_sample_step(widths, activation)
  local cost = R.activation_flop[activation] or error("roofline: no FLOP count for activation '" .. activation .. "'")
  local L = #widths - 1
  local flop, matmul, params = 4 * widths[L + 1], 0, 0
  for l = 0, L - 1 do
    local i, o = widths[l + 1], widths[l + 2]
    local inpad = round_up(i, 4)
    matmul = matmul + 2 * i * o + 2 * o * inpad + (l > 0 and 2 * o * i or 0)
    flop = flop + o  -- the bias gradient
    if l > 0 then flop = flop + i * (cost[1] + 1 + cost[2]) end  -- f(z) forward, f'(z) backward
    params = round_up(params + o * inpad, 8) + round_up(o, 8)  -- each layer's biases from a multiple of 8
  end
  return flop + matmul + 15 * round_up(params, 16) / 8, matmul
end

-- Where build/fma_peak is: beside the running shadenet (/proc/self/exe, so a shadenet found
-- through PATH counts; arg[-1] is only the name it was called by), beside arg[-1] where that
-- names a folder, else in build/ beside this folder's repository. -> path, or nil and the
-- places looked in.
function R.fma_peak_path()
  local dirs = {}
  local ok, ffi = pcall(require, "ffi")
  if ok then
    pcall(ffi.cdef, "long readlink(const char* path, char* buf, unsigned long size);")
    local buf = ffi.new("char[4096]")
    local ok2, n = pcall(ffi.C.readlink, "/proc/self/exe", buf, 4095)
    if ok2 and n > 0 then dirs[#dirs + 1] = ffi.string(buf, n):match("^(.*)/[^/]*$") end
  end
  local called = arg and arg[-1]
  if called and called:find("/") then dirs[#dirs + 1] = called:match("^(.*)/[^/]*$") end
  dirs[#dirs + 1] = ((arg and arg[0] or ""):match("^(.*)/[^/]*$") or ".") .. "/../build"
  local looked = {}
  for _, d in ipairs(dirs) do
    local exe = d .. "/fma_peak"
    local f = io.open(exe, "rb")
    if f then
      f:close()
      return exe
    end
    looked[#looked + 1] = exe
  end
  return nil, looked
end

-- { avx2 = { core = GFLOP/s, all = GFLOP/s }, avx512 = {...}, threads = n } from build/fma_peak
-- (R.fma_peak_path); nil and the reason when it is missing or cannot run.
function R.measure_peak()
  local exe, looked = R.fma_peak_path()
  if not exe then
    return nil, "no fma_peak (looked for " .. table.concat(looked, ", ") .. "; build it: cmake --build build --target fma_peak)"
  end
  local p = io.popen("'" .. exe:gsub("'", "'\\''") .. "' 2>&1")
  local text = p and p:read("*a") or ""
  if p then p:close() end
  local peak = {}
  for isa, core, all, threads in text:gmatch("(%w+) per_core_gflops=([%d.]+) all_cores_gflops=([%d.]+) threads=(%d+)") do
    peak[isa] = { core = tonumber(core), all = tonumber(all) }
    peak.threads = tonumber(threads)
  end
  if not peak.threads then return nil, exe .. " gave no figures: " .. text end
  return peak
end

-- The cores a cpu job of `count` networks can use: one per network, at most the trainer's
-- threads (SHADENET_THREADS, which its device names: "CPU, 2 threads, avx512 kernel") and at
-- most the machine's (`machine`, fma_peak's threads).
function R.cores(count, device, machine)
  local threads = tonumber(tostring(device or ""):match(", (%d+) threads, "))
  return math.min(count, threads or machine, machine)
end

return R

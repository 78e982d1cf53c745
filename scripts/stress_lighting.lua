-- The numerical stress test (issue 3): every lighting model, at its defaults and at the edges of
-- its domain, over an adversarial grid of inputs (n.l and n.v at -1, 0, +-1e-7, grazing, 1;
-- v = l, v = -l, v = the mirror direction; zero-length, tiny, huge and unnormalised vectors),
-- under two lights (oblique, and along +Y where n.l = 0 is exact in float), on the GPU and on
-- the double-precision twin. Prints a Markdown table of NaN / Inf / out-of-range counts, writes
-- it to results/stress_lighting/table.md (+ .csv), and exits 1 unless every count is zero.
--   shadenet scripts/stress_lighting.lua [--quick] [--out DIR] [--help]  (--quick: the same grid, already small)
-- Out of range: raw radiance below 0 or above the model's analytic bound (model:bound()); or a
-- recorded value (clamped, then encoded as rgb / hsv / cie_xyz / cie_lab) outside its space.
package.path = (arg and arg[0] and arg[0]:match("^(.*)/[^/]*$") or ".") .. "/?.lua;" .. package.path
local sn = require "shadenet"

local M = {}

-- One row per stress case: counts summed over both lights.
function M.rows()
  local rows = {}
  for _, case in ipairs(sn.lighting.stress_cases()) do
    local r = sn.lighting.stress(case.model)
    rows[#rows + 1] = {
      case = case.label, samples = r.samples,
      gpu_nan = r.gpu.nan, gpu_inf = r.gpu.inf, gpu_range = r.gpu.negative + r.gpu.over,
      twin_nan = r.twin.nan, twin_inf = r.twin.inf, twin_range = r.twin.negative + r.twin.over,
      recorded_nan = r.encoded_nan, recorded_range = r.encoded_out_of_range,
      max_raw = r.max_raw, failures = r.failures,
    }
  end
  return rows
end

M.columns = {
  { key = "case", header = "model (parameters)", align = "left" },
  { key = "samples", header = "samples" },
  { key = "gpu_nan", header = "GPU NaN" }, { key = "gpu_inf", header = "GPU Inf" },
  { key = "gpu_range", header = "GPU out of range" },
  { key = "twin_nan", header = "twin NaN" }, { key = "twin_inf", header = "twin Inf" },
  { key = "twin_range", header = "twin out of range" },
  { key = "recorded_nan", header = "recorded NaN/Inf" }, { key = "recorded_range", header = "recorded out of range" },
  { key = "max_raw", header = "largest raw value", format = "%.3g" },
}

local function main()
  local results = require "lib.results"
  local cli = require "lib.cli"
  local list = {}
  for i = 1, #arg do list[i] = arg[i] end
  -- The command line every script shares (--help, --out DIR, a value missing is an error), but
  -- for the options of training (--shard, --backend, ...): the stress test trains nothing. Its
  -- grid is small and fixed: --quick runs the same grid.
  local o = cli.parse_or_exit(list, "stress_lighting", nil, function() return nil end, { "--quick", "--out", "--help" })
  local out = o.out
  local rows = M.rows()
  local failures = 0
  for _, r in ipairs(rows) do failures = failures + r.failures end
  local R = results.open({ out = out }, "stress_lighting")
  local md = R:table { title = "Numerical stress test of the lighting models (required: all zero)",
                       columns = M.columns, rows = rows,
                       notes = { string.format("Total failures: %d. GPU: %s.", failures, sn.gl_info().renderer) } }
  io.write(results.read_file(md))
  print("written to " .. md)
  if failures > 0 then
    io.stderr:write(string.format("stress_lighting: %d NaN/Inf/out-of-range outputs\n", failures))
    os.exit(1)
  end
end

-- Run as a script: print and write the table; loaded by a test (dofile): return the module.
if arg and arg[0] and arg[0]:match("stress_lighting%.lua$") then main() end
return M

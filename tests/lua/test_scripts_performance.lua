-- tables_4_5_4_7_performance.lua and pareto.lua in --quick mode: every timing finite and
-- positive, bigger networks cost more, the Pareto front is a front.
local C = require "script_check"
local sn = require "shadenet"

local dir = C.tmpdir("perf")
C.ok("scripts/tables_4_5_4_7_performance.lua", { "--quick", "--out", dir })
C.assert_files(dir, { "table.md", "table.csv", "table_render.md", "table_render.csv", "table_many_nets.csv",
                      "plots/train_time_per_batch.png", "plots/train_time_per_batch.csv", "plots/render_time.png", "run.json" })
local rows = C.csv(dir .. "/table.csv")
local backends = #sn.backends()
assert(#rows == backends * 3 * 3, string.format("%d backends x 3 depths x 3 quick batch sizes, got %d", backends, #rows))
C.assert_range(rows, "ms_per_batch", 1e-6, 1000, "training")
-- table.md shows 3 significant digits of each time, so 0.000486 and 0.000510 ms differ there
-- (with 4 decimals both were 0.0005).
local md = C.read(dir .. "/table.md")
for _, r in ipairs(rows) do
  assert(C.finite(r.thesis_cpu_ms) and C.finite(r.thesis_gpu_ms), "the thesis' rows beside ours")
  local cell = string.format("| %d | %s | %d | %s |", r.layers, r.backend, r.batch, string.format("%.3g", r.ms_per_batch))
  assert(md:find(cell, 1, true), "table.md shows " .. cell .. ":\n" .. md)
end
local render = C.csv(dir .. "/table_render.csv")
assert(#render == 4 * 2, "4 networks x 2 quick image sizes")
C.assert_range(render, "ns_per_fragment", 1e-3, 1e7, "rendering")
C.assert_range(render, "ms_per_call", 1e-3, 1e5, "rendering")
local ns = {}
for _, r in ipairs(render) do
  if r.image == "320x240" then ns[r.network] = r.ns_per_fragment end
end
-- 16x16 does ~16 times the multiply-adds of 4x4 per fragment: it must cost more. (Not a ratio:
-- on the cpu render path a small network's time is mostly the G-buffer read-back, measured
-- 93 vs 168 ns at 320x240; bench/render_throughput.lua is where the figures are.)
assert(ns["16x16"] > ns["4x4"], string.format("16x16 (%.1f ns) vs 4x4 (%.1f ns) per fragment", ns["16x16"], ns["4x4"]))
local many = C.csv(dir .. "/table_many_nets.csv")
assert(#many == backends and many[1].nets == 36, "36 networks per job")
C.rm(dir)

dir = C.tmpdir("pareto")
C.ok("scripts/pareto.lua", { "--quick", "--out", dir })
C.assert_files(dir, { "table.csv", "pareto.md", "plots/pareto_train_phong.png", "plots/pareto_render_ggx.png",
                      "plots/pareto_train_ggx.csv" })
rows = C.csv(dir .. "/table.csv")
assert(#rows == 72, "36 architectures x 2 models")
C.assert_range(rows, "val_mse", 1e-7, 0.05, "pareto")
C.assert_range(rows, "train_s", 1e-5, 1000, "pareto")
C.assert_range(rows, "render_ns", 1e-3, 1e7, "pareto")
-- A front: no architecture is both cheaper and more accurate than one on it, and at least one
-- architecture of each model is on it.
for _, cost in ipairs { { "train_s", "pareto_train" }, { "render_ns", "pareto_render" } } do
  for _, model in ipairs { "phong", "ggx" } do
    local on = 0
    for _, p in ipairs(rows) do
      if p.model == model and p[cost[2]] == "yes" then
        on = on + 1
        for _, q in ipairs(rows) do
          assert(not (q.model == model and q[cost[1]] < p[cost[1]] and q.val_mse < p.val_mse),
                 string.format("%s %s dominates %s on the %s front", model, q.arch, p.arch, cost[1]))
        end
      end
    end
    assert(on >= 1, model .. ": an empty " .. cost[2] .. " front")
    -- ... and every architecture off the front is dominated by one on it.
    for _, p in ipairs(rows) do
      if p.model == model and p[cost[2]] ~= "yes" then
        local dominated = false
        for _, q in ipairs(rows) do
          if q.model == model and q[cost[2]] == "yes" and q[cost[1]] <= p[cost[1]] and q.val_mse <= p.val_mse then
            dominated = true
          end
        end
        assert(dominated, string.format("%s %s is off the %s front but nothing beats it", model, p.arch, cost[1]))
      end
    end
  end
end
C.rm(dir)

-- Stopped after its first training group: it exits 130 at once (it timed every architecture's
-- render first, 12 s more in --quick), and its tables say they are partial.
dir = C.tmpdir("pareto_stopped")
local code, out = C.run_interrupted("scripts/pareto.lua", { "--quick", "--out", dir })
assert(code == 130, "a stopped pareto exits 130, got " .. tostring(code) .. ":\n" .. out)
local md = C.read(dir .. "/table.md")
assert(md:find("**Partial results:** the sweep was stopped (Ctrl-C or SIGTERM) with ", 1, true) and
       md:find("Rendering: not timed", 1, true), md)
local run = C.read(dir .. "/run.json")
assert(not run:find('"render": %d'), "no render timing after the stop:\n" .. run)  -- timings.render, seconds
C.rm(dir)

-- Stopped as its first group begins (its dataset not yet built): no run trains (the whole group
-- trained after the Ctrl-C), the rendering benchmark is not timed, and the message counts the
-- runs not started.
dir = C.tmpdir("performance_stopped")
code, out = C.run_interrupted("scripts/tables_4_5_4_7_performance.lua", { "--quick", "--out", dir }, 0)
assert(code == 130, "a stopped performance script exits 130, got " .. tostring(code) .. ":\n" .. out)
assert(out:find("stopped %(Ctrl%-C or SIGTERM%); 0 of %d+ runs finished and kept in [^\n]*; run the same command to "
                .. "resume %(it trains the 1 stopped part%-way and the %d+ not started%)"), out)
md = C.read(dir .. "/table_render.md")
assert(md:find("Rendering: not timed (the training sweep was stopped", 1, true), md)
assert(not C.read(dir .. "/run.json"):find('"render": %d'), "no render timing after the stop")
C.rm(dir)
print("performance scripts: ok")

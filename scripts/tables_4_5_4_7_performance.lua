-- Tables 4.5-4.7: how fast networks train and render.
-- 4.5: training time per minibatch (ms) of one GGX network of width 8 with 4, 8 and 16 hidden
--      layers against batch size 1..128, on every training backend of this build, beside the
--      thesis' CPU and GPU rows; plus what many networks in one job cost per network (the
--      sweeps' way of training).
-- 4.6: rendering time per frame (ms) of L x L networks (4, 8, 12, 16) at 640x480, 1280x720 and
--      1920x1080, the cloth filling the view as a G-buffer; beside it the GGX ground truth's
--      own pass over the same G-buffer.
-- 4.7: time per covered fragment (ns).
-- Timings are of this machine (run.json names it); the thesis' are of a GTX 1060 and an i7-7700HQ.
--   shadenet scripts/tables_4_5_4_7_performance.lua [--quick] [--shard i/n] [--out DIR] [--backend cpu|gl|auto]
package.path = (arg and arg[0] and arg[0]:match("^(.*)/[^/]*$") or ".") .. "/?.lua;" .. package.path
local sn = require "shadenet"
local exp = require "lib.experiment"
local stats = require "lib.stats"
local thesis = require "lib.thesis"

local E = exp.start("tables_4_5_4_7_performance", arg)

-- ---- Table 4.5: training ----------------------------------------------------------------------
-- A dataset with a 1% validation split, so each epoch's validation pass costs next to nothing
-- beside the minibatches being timed.
local desc = E:data_desc { model = "ggx", split = 0.99 }
local depths = { 4, 8, 16 }
local batches = E:pick({ 1, 8, 128 }, thesis.batches)
local min_batches = E:pick(100, 2000)  -- at least this many minibatches per measurement
local train_rows = math.floor(desc.samples * desc.split)
local backends = E.opts.backend and E.opts.backend ~= "auto" and { E.opts.backend } or sn.backends()
local runs = {}
for _, backend in ipairs(backends) do
  for _, d in ipairs(depths) do
    for _, b in ipairs(batches) do
      local per_epoch = math.floor(train_rows / b)
      runs[#runs + 1] = exp.run { id = string.format("%s-L%02d-b%03d", backend, d, b), hidden = exp.rep(8, d), seed = 1,
                                  batch = b, epochs = math.max(1, math.ceil(min_batches / per_epoch)), data = desc,
                                  backend = backend, alone = true }
    end
  end
  -- The sweeps' way: 36 networks of 8 x 8 trained together, batch 8.
  runs[#runs + 1] = exp.run { id = backend .. "-L08-b008-x36", hidden = exp.rep(8, 8), seed = 1, batch = 8,
                              epochs = math.max(1, math.ceil(min_batches / math.floor(train_rows / 8))), data = desc,
                              backend = backend, alone = true, copies = 36 }
end
local records, interrupted = E:sweep(runs)

local train_rows_out = {}
for _, backend in ipairs(backends) do
  for _, d in ipairs(depths) do
    for _, b in ipairs(batches) do
      local rec = records[string.format("%s-L%02d-b%03d", backend, d, b)]
      local th = thesis.table_4_5[d]
      train_rows_out[#train_rows_out + 1] = {
        layers = d, backend = backend, batch = b,
        ms_per_batch = rec and 1000 * rec.result.wall_time / rec.result.steps or nil,
        batches_timed = rec and rec.result.steps or nil,
        thesis_cpu_ms = th.cpu[b], thesis_gpu_ms = th.gpu[b],
      }
    end
  end
end
local many = {}
for _, backend in ipairs(backends) do
  local rec = records[backend .. "-L08-b008-x36"]
  if rec then
    local ms = 1000 * rec.result.wall_time / rec.result.steps
    many[#many + 1] = { backend = backend, nets = rec.result.job_nets, ms_per_batch_all = ms,
                        ms_per_batch_per_net = ms / rec.result.job_nets,
                        single_net_ms = nil }
    for _, r in ipairs(train_rows_out) do
      if r.backend == backend and r.layers == 8 and r.batch == 8 then many[#many].single_net_ms = r.ms_per_batch end
    end
  end
end

-- ---- Tables 4.6 and 4.7: rendering ----------------------------------------------------------
local sizes = E:pick({ { 160, 120 }, { 320, 240 } }, { { 640, 480 }, { 1280, 720 }, { 1920, 1080 } })
local frames = E:pick(3, 10)
local nets = {}
for _, L in ipairs { 4, 8, 12, 16 } do
  nets[#nets + 1] = { name = L .. "x" .. L, net = sn.mlp { inputs = 6, hidden = exp.rep(L, L), outputs = 3, seed = 1,
                                                           input_names = { "normal", "view" } } }
end
local truth = exp.model("ggx")
local render_rows = {}
-- After Ctrl-C the script stops: the rendering benchmark (8 s of a full run) is not timed.
for _, size in ipairs(interrupted and {} or sizes) do
  -- One view, the cloth filling it: the thesis' screen-space setting.
  local scene = E:scene { mesh = exp.meshes.train, size = size, views = 8 }
  local g = scene:gbuffer { view = 1, attributes = { "normal", "view" } }
  local covered = g:covered()
  local size_name = size[1] .. "x" .. size[2]
  -- The truth pass has no frame count: one call (draw and read-back), median of `frames`.
  local function time_calls(fn)
    fn()
    sn.finish()
    local t = {}
    for i = 1, frames do
      local t0 = sn.clock()
      fn()
      sn.finish()
      t[i] = sn.clock() - t0
    end
    return stats.median(t)
  end
  local truth_s = E:time("render", time_calls, function() return sn.render_truth(g, truth, scene:light()) end)
  for _, n in ipairs(nets) do
    local per_frame, per_call = E:time("render", exp.render_seconds, n.net, g, frames)
    render_rows[#render_rows + 1] = {
      network = n.name, image = size_name, backend = sn.render_info().backend, pixels = size[1] * size[2], covered = covered,
      ms_per_frame = 1000 * per_frame, ns_per_fragment = 1e9 * per_frame / covered, ms_per_call = 1000 * per_call,
      truth_ms_per_call = 1000 * truth_s,
      thesis_ms = thesis.table_4_6[n.name][size_name], thesis_ns_per_fragment = thesis.table_4_7[n.name],
    }
  end
end

-- ---- tables -------------------------------------------------------------------------------------
local info = sn.gl_info()
local device = records[backends[1] .. "-L04-b001"] and records[backends[1] .. "-L04-b001"].result.device or "?"
E.R:table {
  title = "Table 4.5 — training time per minibatch (ms), GGX, width 8",
  grids = {},
  columns = {
    { key = "layers", header = "hidden layers" }, { key = "backend", align = "left" }, { key = "batch" },
    { key = "ms_per_batch", header = "ms / batch (ours)", format = "%.3g" },
    { key = "thesis_cpu_ms", header = "thesis CPU", format = "%.3f" },
    { key = "thesis_gpu_ms", header = "thesis GPU", format = "%.3f" },
    { key = "batches_timed", header = "batches timed" },
  },
  rows = train_rows_out,
  notes = {
    string.format("One network per training job; wall time of the job / its Adam steps (the job's per-epoch validation pass over %d rows included). Device: %s.",
                  desc.samples - train_rows, device),
  },
}
E.R:table {
  file = "table_many_nets",
  title = "Many networks per job: 36 networks of 8 x 8, batch 8",
  columns = {
    { key = "backend", align = "left" }, { key = "nets" },
    { key = "ms_per_batch_all", header = "ms per step of all nets", format = "%.3g" },
    { key = "ms_per_batch_per_net", header = "ms per batch per net", format = "%.3g" },
    { key = "single_net_ms", header = "one net alone: ms per batch", format = "%.3g" },
  },
  rows = many,
}
E.R:table {
  file = "table_render",
  title = "Tables 4.6 and 4.7 — rendering time per frame (ms) and per covered fragment (ns)",
  grids = {
    { title = "ms per frame, ours (thesis)", rows = "network", cols = "image", value = "ms_per_frame",
      thesis = "thesis_ms", format = "%.3f" },
    { title = "ns per covered fragment, ours (thesis, one value per network)", rows = "network", cols = "image",
      value = "ns_per_fragment", thesis = "thesis_ns_per_fragment", format = "%.1f" },
  },
  columns = {
    { key = "network", align = "left" }, { key = "image" }, { key = "backend", align = "left" }, { key = "covered", header = "covered fragments" },
    { key = "ms_per_frame", header = "ms / frame (drawing)", format = "%.3g" },
    { key = "ns_per_fragment", header = "ns / fragment", format = "%.1f" },
    { key = "ms_per_call", header = "ms / call (draw + read-back)", format = "%.3g" },
    { key = "truth_ms_per_call", header = "GGX truth pass, ms / call", format = "%.3g" },
    { key = "thesis_ms", header = "thesis ms / frame", format = "%.3f" },
    { key = "thesis_ns_per_fragment", header = "thesis ns / fragment", format = "%.1f" },
  },
  rows = render_rows,
  notes = {
    string.format("Drawing: one net:render call of %d + 1 frames less a call of 1 frame, after a warm-up, timed to sn.finish() (no read-back of the image in it). "
                  .. "Renderer: %s; the backend column is what net:render's auto chose (cpu: the network's kernels over the covered G-buffer pixels, "
                  .. "attribute read-back included; gl: the fragment shader).", frames, info.renderer),
    "A call: one frame drawn and read back into an image; the GGX truth pass over the same G-buffer, for scale (median of the same number of calls).",
    interrupted and "Rendering: not timed (the training sweep was stopped; run the same command to finish both)." or nil,
  },
}

-- Plots: ms per batch against batch size (log-log), one line per depth and backend, thesis dashed.
-- One colour per depth; ours: cpu solid, gl dashed; the thesis: CPU open circles, GPU open squares.
local depth_color = { [4] = "#1f77b4", [8] = "#2ca02c", [16] = "#d62728" }
local series = {}
for k, backend in ipairs(backends) do
  for _, d in ipairs(depths) do
    local s = { name = string.format("%d layers %s (ours)", d, backend), x = {}, y = {}, style = "linespoints",
                color = depth_color[d], dash = k }
    for _, r in ipairs(train_rows_out) do
      if r.backend == backend and r.layers == d and r.ms_per_batch then
        s.x[#s.x + 1], s.y[#s.y + 1] = r.batch, r.ms_per_batch
      end
    end
    series[#series + 1] = s
  end
end
for _, d in ipairs(depths) do
  for _, dev in ipairs { "cpu", "gpu" } do
    local s = { name = string.format("%d layers thesis %s", d, dev:upper()), x = {}, y = {}, style = "points",
                color = depth_color[d], point = dev == "cpu" and 6 or 4 }
    for _, b in ipairs(batches) do s.x[#s.x + 1], s.y[#s.y + 1] = b, thesis.table_4_5[d][dev][b] end
    series[#series + 1] = s
  end
end
E:plot("plots/train_time_per_batch.png", { title = "Table 4.5 — training time per minibatch, GGX, width 8",
  xlabel = "batch size", ylabel = "ms per batch", logx = true, logy = true, series = series, key = "outside right",
  width = 1000 })

-- Rendering: one colour per network; ours solid, the thesis' (GTX 1060) dashed with open squares.
local net_color = { ["4x4"] = "#1f77b4", ["8x8"] = "#2ca02c", ["12x12"] = "#ff7f0e", ["16x16"] = "#d62728" }
series = {}
for _, n in ipairs(nets) do
  local s = { name = n.name .. " (ours)", x = {}, y = {}, style = "linespoints", color = net_color[n.name] }
  local t = { name = n.name .. " (thesis: GTX 1060)", x = {}, y = {}, style = "linespoints", color = net_color[n.name],
              dash = 2, point = 4 }
  for _, r in ipairs(render_rows) do
    if r.network == n.name then
      s.x[#s.x + 1], s.y[#s.y + 1] = r.pixels / 1e6, r.ms_per_frame
      if r.thesis_ms then t.x[#t.x + 1], t.y[#t.y + 1] = r.pixels / 1e6, r.thesis_ms end
    end
  end
  series[#series + 1] = s
  if #t.x > 0 then series[#series + 1] = t end
end
if #render_rows > 0 then  -- none when the sweep was stopped
  E:plot("plots/render_time.png", { title = "Table 4.6 — rendering time per frame, ours and the thesis'",
    xlabel = "image size (megapixels)", ylabel = "ms per frame", logy = true, series = series, key = "outside right",
    width = 1000 })
end

E:finish {
  records = records,
  config = { model = "ggx", depths = depths, batches = batches, min_batches = min_batches, backends = backends,
             data = desc, render_sizes = sizes, frames = frames },
  summary = { training = train_rows_out, many_nets = many, rendering = render_rows },
}

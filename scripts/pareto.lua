-- Run time against error: which network should I use for this lighting model and this budget?
-- Trains the 36 architectures of tables 4.1 / 4.2 (2..12 hidden layers x 2..12 neurons) on Phong
-- and on GGX, each network in a training job of its own so its training time is its own, then
-- times each architecture's rendering (ns per covered fragment). Plots median validation MSE
-- against training time and against rendering cost, marks the Pareto-optimal architectures
-- (nothing else is both faster and more accurate), and lists them as a table.
--   shadenet scripts/pareto.lua [--quick] [--shard i/n] [--out DIR] [--backend cpu|gl|auto]
package.path = (arg and arg[0] and arg[0]:match("^(.*)/[^/]*$") or ".") .. "/?.lua;" .. package.path
local sn = require "shadenet"
local exp = require "lib.experiment"
local stats = require "lib.stats"
local thesis = require "lib.thesis"

local E = exp.start("pareto", arg)
local sizes = thesis.sizes
local models = { "phong", "ggx" }
local seeds = E:pick(1, 3)
local epochs = E:pick(10, exp.epochs)
local frames = E:pick(5, 10)
local runs, descs = {}, {}
for _, m in ipairs(models) do
  descs[m] = E:data_desc { model = m }
  for seed = 1, seeds do
    for _, l in ipairs(sizes) do
      for _, w in ipairs(sizes) do
        runs[#runs + 1] = exp.run { id = string.format("%s-L%02d-W%02d-s%02d", m, l, w, seed), hidden = exp.rep(w, l),
                                    seed = seed, epochs = epochs, data = descs[m], alone = true }
      end
    end
  end
end
local records = E:sweep(runs)

-- Rendering cost per architecture: the cloth at the render size, one view; a network's speed
-- does not depend on its weights, so a freshly initialised one is timed. Not after a Ctrl-C:
-- the partial results are written at once, without the cost columns.
local render_ns, size, covered = {}, E:pick({ 160, 120 }, { 640, 480 }), nil
if not E.interrupted then
  local scene = E:scene { mesh = exp.meshes.train, size = size, views = 8 }
  local g = scene:gbuffer { view = 1, attributes = { "normal", "view" } }
  covered = g:covered()
  for _, l in ipairs(sizes) do
    for _, w in ipairs(sizes) do
      local net = sn.mlp { inputs = 6, hidden = exp.rep(w, l), outputs = 3, seed = 1, input_names = { "normal", "view" } }
      local per_frame = E:time("render", exp.render_seconds, net, g, frames)
      render_ns[l .. "x" .. w] = 1e9 * per_frame / covered
    end
  end
end

-- Pareto front of points over (cost, err): sorted by cost, each point better than all cheaper ones.
local function pareto(points, cost, err)
  local sorted = {}
  for _, p in ipairs(points) do if p[err] and p[cost] then sorted[#sorted + 1] = p end end
  table.sort(sorted, function(a, b) return a[cost] < b[cost] or (a[cost] == b[cost] and a[err] < b[err]) end)
  local best, front = math.huge, {}
  for _, p in ipairs(sorted) do
    if p[err] < best then
      best = p[err]
      front[#front + 1] = p
    end
  end
  return front
end

local rows = {}
for _, m in ipairs(models) do
  local points = {}
  for _, l in ipairs(sizes) do
    for _, w in ipairs(sizes) do
      local ids, times = {}, {}
      for seed = 1, seeds do
        local id = string.format("%s-L%02d-W%02d-s%02d", m, l, w, seed)
        ids[#ids + 1] = id
        if records[id] then times[#times + 1] = records[id].result.wall_time end
      end
      local mse = exp.median_of(records, ids, "best_val_mse")
      points[#points + 1] = exp.with_unseen({
        model = m, layers = l, width = w, arch = l .. "x" .. w, parameters = exp.param_count(6, exp.rep(w, l), 3),
        val_mse = mse, train_s = stats.median(times), render_ns = render_ns[l .. "x" .. w],
      }, records, ids)
    end
  end
  -- Error on the training data's validation rows, and on meshes no network saw (the error a
  -- user of the network meets).
  local fronts = {
    { key = "pareto_train", cost = "train_s", err = "val_mse" },
    { key = "pareto_render", cost = "render_ns", err = "val_mse" },
    { key = "pareto_unseen", cost = "render_ns", err = "unseen_mse" },
  }
  for _, f in ipairs(fronts) do
    f.front = pareto(points, f.cost, f.err)
    local on = {}
    for _, p in ipairs(f.front) do on[p] = true end
    for _, p in ipairs(points) do p[f.key] = on[p] and "yes" or "" end
  end
  for _, p in ipairs(points) do rows[#rows + 1] = p end
  local function plot(cost, err, front, xlabel, ylabel, file)
    local all = { name = "all architectures", x = {}, y = {}, style = "points", labels = {}, color = "#1f77b4" }
    for _, p in ipairs(points) do
      if p[err] and p[cost] then
        all.x[#all.x + 1], all.y[#all.y + 1], all.labels[#all.labels + 1] = p[cost], p[err], p.arch
      end
    end
    if #all.x == 0 then return end  -- nothing measured (a stopped sweep's render costs): no plot
    local f = { name = "Pareto-optimal", x = {}, y = {}, style = "linespoints", color = "#d62728" }
    for _, p in ipairs(front) do f.x[#f.x + 1], f.y[#f.y + 1] = p[cost], p[err] end
    E:plot(file, { title = string.format("%s: %s against %s (labels: layers x width)",
                                         m == "ggx" and "GGX" or "Phong", ylabel, xlabel),
                   xlabel = xlabel, ylabel = ylabel, logx = true, logy = true,
                   series = { all, f }, width = 900, height = 600 })
  end
  plot("train_s", "val_mse", fronts[1].front, "training time per network (s)", "median min. validation MSE",
       "plots/pareto_train_" .. m .. ".png")
  plot("render_ns", "val_mse", fronts[2].front, "rendering cost (ns per fragment)", "median min. validation MSE",
       "plots/pareto_render_" .. m .. ".png")
  plot("render_ns", "unseen_mse", fronts[3].front, "rendering cost (ns per fragment)",
       "median image MSE on unseen meshes", "plots/pareto_unseen_" .. m .. ".png")
end

E.R:table {
  title = "Run time against error: Pareto-optimal architectures (yes) for training time and for rendering cost",
  columns = {
    { key = "model", align = "left" }, { key = "arch", header = "layers x width" }, { key = "parameters" },
    { key = "val_mse", header = "median min val MSE", format = "%.4g" },
    { key = "train_s", header = "train s / network", format = "%.3f" },
    { key = "render_ns", header = "render ns / fragment", format = "%.1f" },
    exp.unseen_columns[1], exp.unseen_columns[2],
    { key = "pareto_train", header = "Pareto (train time)" }, { key = "pareto_render", header = "Pareto (render)" },
    { key = "pareto_unseen", header = "Pareto (render, unseen-mesh error)" },
  },
  rows = rows,
  notes = {
    string.format("Median over %d seeds; %s, tanh; each network trained alone (%s backend); training data: %s.",
                  seeds, exp.recipe(epochs), E.backend, E:data_note()),
    exp.unseen_note(),
    covered and string.format("Rendering: %d frames drawn at %dx%d (%d covered fragments) in one call, less a one-frame call: drawing only, no read-back; %s.",
                              frames, size[1], size[2], covered, sn.gl_info().renderer)
            or "Rendering: not timed (the sweep was stopped by Ctrl-C or SIGTERM).",
  },
}
-- The answer in short: per model, the Pareto-optimal architectures from cheapest to most accurate.
local short = {}
for _, r in ipairs(rows) do
  if r.pareto_train == "yes" or r.pareto_render == "yes" or r.pareto_unseen == "yes" then short[#short + 1] = r end
end
table.sort(short, function(a, b)
  if a.model ~= b.model then return a.model > b.model end
  return (a.train_s or 0) < (b.train_s or 0)
end)
E.R:table {
  file = "pareto",
  title = "Which network for which budget: the Pareto-optimal architectures only",
  columns = {
    { key = "model", align = "left" }, { key = "arch", header = "layers x width" },
    { key = "val_mse", header = "median min val MSE", format = "%.4g" },
    { key = "train_s", header = "train s", format = "%.3f" },
    { key = "render_ns", header = "render ns / fragment", format = "%.1f" },
    exp.unseen_columns[1],
    { key = "pareto_train", header = "best for training time" }, { key = "pareto_render", header = "best for rendering" },
    { key = "pareto_unseen", header = "best for rendering, unseen meshes" },
  },
  rows = short,
}
E:finish {
  records = records,
  config = { models = models, sizes = sizes, seeds = seeds, epochs = epochs, batch = exp.batch, adam = exp.adam,
             data = descs, render = { size = size, frames = frames, covered = covered } },
  summary = { rows = rows },
}

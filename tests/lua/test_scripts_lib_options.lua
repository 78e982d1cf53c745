-- scripts/lib's option tables are strict: a misspelled key is an error naming the line of the
-- script that passed it (this file's, never a line of scripts/lib), the key and the valid keys
-- (with the near ones); a missing required key is an error naming it. Nothing here trains.
package.path = "scripts/?.lua;" .. package.path
local sn = require "shadenet"
local exp = require "lib.experiment"
local results = require "lib.results"
local Sweep = require "lib.sweep"
local plot = require "lib.plot"
local Progress = require "lib.progress"
local depth_width = require "lib.depth_width"
local grids = require "lib.grids"

local tmp = sn.fs.tempdir("test_scripts_lib_options")
local here = debug.getinfo(1, "S").short_src  -- as error messages name this file

-- fails(f, ...texts): f() raises an error that starts with this file and the line f is defined
-- on (each f calls the library on its first line) and holds every text.
local function fails(f, ...)
  local line = debug.getinfo(f, "S").linedefined
  local ok, err = pcall(f)
  assert(not ok, "line " .. line .. ": no error")
  err = tostring(err)
  local where = here .. ":" .. line .. ": "
  assert(err:sub(1, #where) == where, ("line %d: the error does not name %s: %s"):format(line, where, err))
  assert(not err:find("scripts/lib/", 1, true), ("line %d: the error names the library: %s"):format(line, err))
  for i = 1, select("#", ...) do
    local text = select(i, ...)
    assert(err:find(text, 1, true), ("line %d: %q does not hold %q"):format(line, err, text))
  end
  return err
end

-- ---- sn.near: the names near a typo (one edit in four characters; a swap of neighbours is one) ----
local near = sn.near("sampels", { "model", "samples", "seed", "split" })
assert(#near == 1 and near[1] == "samples", "a swap is one edit: " .. table.concat(near, ","))
assert(#sn.near("epoch", { "epochs", "batch" }) == 1 and #sn.near("zzz", { "epochs" }) == 0, "sn.near")
fails(function() return sn.trian end, "sn.trian is not part of shadenet (did you mean sn.train?)")

-- ---- lib.experiment ----
local E = exp.start("options_check", { "--quick", "--out", tmp .. "/x" })
fails(function() E:data_desc { model = "phong", sampels = 100 } end,
      "E:data_desc: unknown option 'sampels'", "did you mean samples?",
      "(valid: model, inputs, vary, color, samples, split, seed, data, mesh")
fails(function() E:data_desc { modle = "ggx" } end, "unknown option 'modle'", "did you mean model?")
fails(function() E:data { model = "phong", input = { "normal" } } end, "unknown option 'input'", "did you mean inputs?")
fails(function() E:baseline { model = "phong", colour = "hsv" } end, "unknown option 'colour'", "did you mean color?")
fails(function() E:scene { mesh = exp.meshes.train, view = 4 } end,
      "E:scene: unknown option 'view'", "did you mean views?", "valid: mesh, size, views, elevation, light, poses")
local desc = E:data_desc { model = "phong" }
fails(function() E:data_desc { scene = desc.scene, model = "phong" } end,
      "E:data_desc (a description) option 'truth' is required")
fails(function() exp.run { id = "a", hidden = { 4 }, seed = 1, epoch = 2, data = desc } end,
      "exp.run: unknown option 'epoch'", "did you mean epochs?",
      "valid: id, hidden, data, seed, epochs, batch, adam, outputs")
fails(function() exp.run { id = "a", hidden = { 4 }, seed = 1 } end,
      "exp.run option 'data' is required (a dataset description: E:data_desc{...})")
fails(function() exp.run { hidden = { 4 }, seed = 1, data = desc } end, "exp.run option 'id' is required")
fails(function() exp.run { id = "a", seed = 1, data = desc } end, "exp.run option 'hidden' is required")
fails(function() exp.run { id = "a", hidden = { 4 }, data = desc } end, "exp.run option 'seed' is required")
fails(function() exp.run { id = "a", hidden = { 4 }, seed = 1, data = { model = "phong" } } end,
      "exp.run option 'data' is not a dataset description")
fails(function() exp.run("a") end, "exp.run: options table expected, got string")
fails(function() exp.run { id = "a", hidden = { 4 }, seed = 1, data = desc, "x" } end, "exp.run: options must be named")
-- Every key the docs list for exp.run is taken (the run is never trained: sine reads no slope).
local run = exp.run { id = "a", hidden = { 4 }, data = desc, seed = 1, epochs = 2, batch = 4, adam = exp.adam,
                      outputs = 3, activation = "sine", slope = 0.1, omega = 2, alpha = 1,
                      output_activation = "linear", init = "xavier", encoding = { normal = { "frequency", bands = 2 } },
                      keep_params = true, tag = "t", backend = "cpu", alone = true, copies = 2 }
assert(run.config.epochs == 2 and run.config.batch == 4 and run.config.copies == 2 and run.config.job == "a", "exp.run")
fails(function() E:sweep({ run }, { chunks = 2 }) end,
      "E:sweep: unknown option 'chunks'", "did you mean chunk?", "valid: chunk, label")
fails(function() E:compare { file = "figures/c.png", model = "phong", nets = {}, meshes = {}, colour_shfit = true } end,
      "E:compare: unknown option 'colour_shfit'", "did you mean colour_shift?")
fails(function() E:compare { file = "figures/c.png", nets = {}, meshes = {} } end,
      "E:compare option 'model' is required")
local typo_mesh = { { mesh = exp.meshes.train, label = "m", veiws = { 1 } } }
fails(function() E:compare { file = "figures/c.png", model = "phong", nets = {}, meshes = typo_mesh } end,
      "E:compare meshes[1]: unknown option 'veiws'", "did you mean views?")
fails(function() E:plot("plots/p.png", { title = "t", serie = {} }) end,
      "E:plot: unknown option 'serie'", "did you mean series?")
fails(function() E:finish { record = {} } end,
      "E:finish: unknown option 'record'", "did you mean records?", "valid: records, config, summary")
fails(function() exp.start("options_check", { "--quick", "--out", tmp .. "/y" }, { flag = {} }) end,
      "exp.start: unknown option 'flag'", "did you mean flags?")

-- ---- lib.results ----
local R = results.open({ out = tmp .. "/r" }, "r")
local rows = { { layers = 4, width = 6, v = 1 } }
fails(function() R:table { titel = "T", columns = { { key = "v" } }, rows = rows } end,
      "R:table: unknown option 'titel'", "did you mean title?", "valid: file, title, columns, rows, grids, notes")
fails(function() R:table { title = "T", columns = { { key = "v" } } } end, "R:table option 'rows' is required")
fails(function() R:table { columns = { { key = "v", fromat = "%.2f" } }, rows = rows } end,
      "R:table columns[1]: unknown option 'fromat'", "did you mean format?", "valid: key, header, format, align")
local typo_grid = { { rows = "layers", col = "width", value = "v" } }
fails(function() R:table { columns = { { key = "v" } }, rows = rows, grids = typo_grid } end,
      "R:table grids[1]: unknown option 'col'", "did you mean cols?")
fails(function() results.markdown_grid({ rows = "layers", cols = "width" }, rows) end,
      "results.markdown_grid option 'value' is required")

-- ---- lib.sweep ----
local sweep = Sweep.new { dir = tmp .. "/sw", runs = { { id = "one", config = { x = 1 } } }, label = "t" }
fails(function() sweep:run { trian = function() end } end,
      "sweep:run: unknown option 'trian'", "did you mean train?", "valid: train, group_key, chunk, score, describe")
fails(function() sweep:run { chunk = 2 } end, "sweep:run option 'train' is required")
fails(function() Sweep.new { dir = tmp .. "/sw", run = {} } end,
      "Sweep.new: unknown option 'run'", "did you mean runs?")
fails(function() Sweep.new { dir = tmp .. "/sw" } end, "Sweep.new option 'runs' is required")

-- ---- lib.plot, lib.progress ----
local series = { { name = "a", x = { 1 }, y = { 1 } } }
fails(function() plot.lines { path = tmp .. "/p.png", series = series, logY = true } end,
      "plot.lines: unknown option 'logY'", "did you mean logx, logy?")
local typo_series = { { name = "a", x = { 1 }, y = { 1 }, colour = "#ff0000" } }
fails(function() plot.lines { path = tmp .. "/p.png", series = typo_series } end,
      "plot.lines series[1]: unknown option 'colour'", "did you mean color?")
fails(function() plot.lines { path = tmp .. "/p.png", series = { { x = { 1 }, y = { 1 } } } } end,
      "plot.lines series[1] option 'name' is required")
fails(function() Progress.new { totl = 3 } end, "Progress.new: unknown option 'totl'", "did you mean total?")

-- ---- lib.depth_width, lib.grids ----
fails(function() depth_width.run(E, { model = "phong", thesis = {}, size = { 2 } }) end,
      "depth_width.run: unknown option 'size'", "did you mean sizes?")
fails(function() grids.run(E, { model = "phong" }) end, "grids.run option 'figures' is required")

print("scripts/lib options: strict")

-- What every experiment script shares, so each script only says what it varies:
--   local E = exp.start("table_4_1_phong", arg)      -- command line, results folder, clock
--   local data = E:data { model = "phong" }           -- the thesis' dataset (built lazily)
--   local records = E:sweep(runs)                     -- train, resume, shard; records by id
--   E:finish { ... }                                  -- run.json
-- A run's config says everything its result depends on (architecture, seed, epochs, Adam,
-- dataset); runs sharing the training settings train together in one sn.train job.
local sn = require "shadenet"
local cli = require "lib.cli"
local claim = require "lib.claim"
local results = require "lib.results"
local Sweep = require "lib.sweep"
local stats = require "lib.stats"
local json = require "lib.json"
local plot = require "lib.plot"
local Progress = require "lib.progress"
local options = require "lib.options"

local exp = {}
local E = {}
E.__index = E
exp.Experiment = E  -- the methods every experiment object has (scripts may wrap them)

-- The thesis' training settings (Adam(0.00025, 0.8, 0.9), batch 8, 20 epochs).
exp.adam = { lr = 0.00025, beta1 = 0.8, beta2 = 0.9 }
exp.batch = 8
exp.epochs = 20
-- "20 epochs, batch 8, Adam(0.00025, 0.8, 0.9)": the training recipe the notes print (`adam`
-- defaults to exp.adam).
function exp.recipe(epochs, adam)
  adam = adam or exp.adam
  return string.format("%d epochs, batch %d, Adam(%g, %g, %g)", epochs, exp.batch, adam.lr, adam.beta1, adam.beta2)
end

-- ---- start ----------------------------------------------------------------------------------

-- exp.start(name, arg [, { flags = {...extra cli flags}, backend = "auto" }]) -> E
function exp.start(name, args, o)
  o = options.check(o or {}, "exp.start", { "flags", "backend" })
  local list = {}
  for i = 1, #(args or {}) do list[i] = args[i] end
  -- scripts/merge.lua reports on every run: a Slurm array task it runs in picks no shard.
  local opts = cli.parse_or_exit(list, name, o.flags, exp.report_only and function() return nil end or nil)
  local R = results.open(opts, name)
  -- The script's own flags as given (run.json records them; merge.lua gives them again).
  local own_flags = {}
  for _, f in ipairs(o.flags or {}) do
    local key = f.flag:sub(3):gsub("-", "_")
    if opts.extra[key] ~= nil then own_flags[f.flag] = opts.extra[key] end
  end
  -- The folder holds this experiment, in this mode, on this data, with these flags (lib.claim).
  local d = cli.defaults
  local folder = claim.folder(R.dir, { experiment = name, quick = opts.quick,
                                       options = { data = opts.data or d.data, ggx = opts.ggx or d.ggx },
                                       flags = claim.flag_values(own_flags) })
  local self = setmetatable({
    name = name, opts = opts, quick = opts.quick, R = R, dir = R.dir, args = list, own_flags = own_flags,
    claim = folder,
    -- the script as it was run (a user's own experiment may live anywhere); merge.lua runs it
    script = args and type(args[0]) == "string" and args[0] or "scripts/" .. name .. ".lua",
    backend = opts.backend or o.backend or "auto",
    data_choice = opts.data or cli.defaults.data,
    ggx_choice = opts.ggx or cli.defaults.ggx,
    t0 = sn.clock(), timings = {}, datasets = {}, scenes = {}, sweeps = {}, baselines = {},
    load_at_start = results.load_average(),
  }, E)
  -- Every table says when it is not the full experiment: quick mode, or one shard's runs.
  R.notices = {}
  if opts.quick then
    R.notices[#R.notices + 1] = "**Quick mode (--quick):** fewer seeds and epochs, 8,000 samples and smaller images: a "
                                .. "smoke run, not the thesis' recipe; its numbers are not the experiment's."
  end
  if opts.shard then
    R.notices[#R.notices + 1] = string.format("**One shard (%d/%d%s):** this shard trained only its own runs; the "
                                              .. "table holds those and any others already in its folder, – marks "
                                              .. "the rest. Merge the shards with scripts/merge.lua.",
                                              opts.shard.index, opts.shard.count,
                                              opts.shard.from and ", from " .. opts.shard.from or "")
  end
  exp.model_params.ggx = exp.ggx_presets[self.ggx_choice]
  exp.ggx_used = false  -- this experiment's notes name the GGX only if it uses one
  local shard = opts.shard and string.format(" shard %d/%d%s", opts.shard.index, opts.shard.count,
                                             opts.shard.from and " (" .. opts.shard.from .. ")" or "") or ""
  print(string.format("%s%s%s: results in %s/", name, opts.quick and " --quick" or "", shard, R.dir))
  return self
end

-- Runs fn() and adds its wall time to timings[label].
function E:time(label, fn, ...)
  local t0 = sn.clock()
  local a, b, c = fn(...)
  self.timings[label] = (self.timings[label] or 0) + (sn.clock() - t0)
  return a, b, c
end

-- q(quick_value, full_value)
function E:pick(quick, full)
  if self.quick then return quick end
  return full
end

-- ---- data -----------------------------------------------------------------------------------

-- The meshes: the cloth the thesis trains on, and a different mesh to test generalisation.
exp.meshes = { train = "meshes/cloth.glb", test = "meshes/test_blob.glb" }

-- The default training data (--data poses): the cloth in 5 poses, upright and tilted by +-60
-- degrees about x and about z, each seen from 3 rings of views (elevations -30, 20 and 60
-- degrees; 8 views each in full mode). The hanging cloth alone seen from one ring (--data cloth,
-- the thesis' data) has no normal pointing further up than y = 0.40 and one camera height, so
-- its networks never see the highlight zone of most other meshes; tilted and seen from three
-- heights, the rows cover the normal sphere and the view hemisphere.
exp.poses = { {}, { rotate = { 60, 1, 0, 0 } }, { rotate = { -60, 1, 0, 0 } },
              { rotate = { 60, 0, 0, 1 } }, { rotate = { -60, 0, 0, 1 } } }
exp.pose_elevations = { -30, 20, 60 }

-- Meshes no network trains on, for the generalisation every script reports: the test blob, two
-- glTF sample models and two procedural shapes, each seen from three elevations.
exp.unseen_meshes = {
  { label = "test blob", mesh = "meshes/test_blob.glb" },
  { label = "Duck", mesh = "../shared/meshes/Duck.gltf" },
  { label = "Box", mesh = "../shared/meshes/Box.gltf" },
  { label = "sphere", mesh = function() return sn.mesh.sphere {} end },
  { label = "torus", mesh = function() return sn.mesh.torus {} end },
}
-- One camera per ring, at three elevations and three azimuths (rings of 3, camera k of ring k).
exp.unseen_rings = { { count = 3, elevation = -30 }, { count = 3, elevation = 20 }, { count = 3, elevation = 60 } }
exp.unseen_views = { 1, 5, 9 }

-- The scene the thesis' samples come from: the cloth mesh seen from an orbit of views. Full mode
-- samples 64,149 covered pixels like the thesis; quick mode a few thousand from small images.
function E:scene_options(o)
  o = o or {}
  return {
    mesh = o.mesh or exp.meshes.train,
    size = o.size or self:pick({ 160, 120 }, { 640, 480 }),
    views = o.views or self:pick(4, 8),
    elevation = o.elevation or 20,
    light = o.light or { dir = { 0.5, 0.7, 0.6 } },
    poses = o.poses,
  }
end

-- so.elevation: one ring's elevation, or a list of them (one ring of so.views cameras each).
function exp.make_scene(so)
  local views = { count = so.views, elevation = so.elevation }
  if type(so.elevation) == "table" then
    views = {}
    for i, e in ipairs(so.elevation) do views[i] = { count = so.views, elevation = e } end
  end
  return sn.scene { mesh = so.mesh, size = so.size, views = views, light = so.light, poses = so.poses }
end

-- The scene for options `o` (cached per process by its options).
exp.scene_keys = { "mesh", "size", "views", "elevation", "light", "poses" }
-- A mesh given as a value (not a path) is keyed by its identity: JSON cannot hold it.
local mesh_ids, mesh_count = setmetatable({}, { __mode = "k" }), 0
function E:scene(o)
  local so = self:scene_options(options.check(o or {}, "E:scene", exp.scene_keys))
  local key_options = so
  if type(so.mesh) == "userdata" then
    if not mesh_ids[so.mesh] then
      mesh_count = mesh_count + 1
      mesh_ids[so.mesh] = "mesh value " .. mesh_count
    end
    key_options = { mesh = mesh_ids[so.mesh] }
    for k, v in pairs(so) do if k ~= "mesh" then key_options[k] = v end end
  end
  local key = json.encode(key_options)
  if not self.scenes[key] then
    self.scenes[key] = self:time("scene", exp.make_scene, so)
  end
  return self.scenes[key], so
end

-- The lighting model `spec` names: "phong", "ggx", "toon3", "textured_phong" (or a model of
-- one's own, by name), { name = "ggx", params = {...} } (or { "ggx", {...} }), or a Lighting
-- value itself.
function exp.model(spec)
  if type(spec) == "userdata" then return spec end
  local name = type(spec) == "string" and spec or type(spec) == "table" and (spec.name or spec[1])
  if type(name) ~= "string" then
    options.error("a lighting model expected (a name, { name = ..., params = {...} } or a Lighting value), got "
                  .. type(spec))
  end
  if name == "ggx" then exp.ggx_used = true end
  local params = type(spec) == "table" and (spec.params or spec[2]) or nil
  return sn.lighting.new(name, params or exp.model_params[name] or {})
end

-- GGX ground truths (--ggx). The thesis prints no GGX parameters; the one number it gives about
-- its GGX data is the MSE of an all-zeros output, 0.28633 (fig. 4.11's stalled networks).
-- "thesis" (the default) is the ground-truth module's gold metal with a grey diffuse term and a
-- brighter ambient, calibrated so that MSE is 0.2851 on the default data (full mode), within
-- 0.5% of the thesis', so absolute MSEs compare with its tables as well as rankings. "gold" is
-- the module's metal as it stands (no diffuse term, ambient 0.1): its all-zeros MSE is 0.052,
-- 5.5x below the thesis'.
exp.ggx_presets = { thesis = { diffuse = 0.58, ambient = 0.2 }, gold = {} }
exp.ggx_notes = {
  thesis = "GGX calibrated to the thesis' all-zeros MSE (--ggx thesis, the default: diffuse 0.58, ambient 0.2)",
  gold = "GGX: the gold metal (--ggx gold: no diffuse term, ambient 0.1)",
}

-- The ground truths of chapter 4, as the ground-truth module defines them, GGX as --ggx chose
-- (exp.start sets it; exp.model records that a run used it, for E:data_note).
exp.model_params = {
  phong = {},
  ggx = {},
  toon3 = {},
  textured_phong = {},
}

-- E:data_desc{ model = "phong", inputs = {"normal", "view"}, color = "rgb", samples = N, split = 0.8,
--              seed = 1, data = "poses"|"cloth", mesh, size, views, elevation, light, poses }
--   -> the dataset's description (what a run's config records); given a description, returns it.
exp.data_keys = { "model", "inputs", "vary", "color", "samples", "split", "seed", "data", "mesh", "size", "views",
                  "elevation", "light", "poses" }
exp.desc_required = { "model", "truth", "inputs", "color", "samples", "split", "seed", "scene" }
exp.desc_keys = { "model", "truth", "truth_definition", "inputs", "vary", "color", "samples", "split", "seed", "scene",
                  "mesh_key" }
-- The training mesh's content key (mesh:key()), a file read once per process: a mesh rewritten
-- under the same path is new data, and its runs are trained again.
local mesh_keys = {}
local function mesh_key(mesh)
  if type(mesh) ~= "string" then return mesh:key() end
  mesh_keys[mesh] = mesh_keys[mesh] or sn.mesh.load(mesh):key()
  return mesh_keys[mesh]
end
-- The inputs a description names: G-buffer attributes (the runtime's list) and the parameters it
-- varies, each of those among the inputs; checked here, at the script's line, before anything is
-- rendered (a name the library did not know failed after the dataset was built).
local function check_inputs(inputs, vary)
  if type(inputs) ~= "table" or #inputs == 0 then
    options.error("E:data_desc option 'inputs': a list of input names expected, e.g. { \"normal\", \"view\" }")
  end
  if vary ~= nil and type(vary) ~= "table" then
    options.error("E:data_desc option 'vary': { parameter = {min, max}, ... } expected, got " .. type(vary))
  end
  local valid = sn.dataset.attributes()
  local known = {}
  for _, a in ipairs(valid) do known[a] = true end
  for _, a in ipairs(inputs) do
    if not known[a] and not (vary and vary[a]) then
      options.error(string.format("E:data_desc option 'inputs': '%s' is not a G-buffer attribute (%s) nor a parameter "
                                  .. "in vary", tostring(a), table.concat(valid, ", ")))
    end
  end
  for p in pairs(vary or {}) do
    local listed = false
    for _, a in ipairs(inputs) do listed = listed or a == p end
    if not listed then
      options.error(string.format("E:data_desc option 'vary': the varied parameter '%s' must be in inputs too "
                                  .. "(where the network reads it)", tostring(p)))
    end
  end
end
function E:data_desc(o)
  o = o or {}
  if type(o) == "table" and o.scene then  -- already a description
    return options.check(o, "E:data_desc (a description)", exp.desc_keys, exp.desc_required)
  end
  options.check(o, "E:data_desc", exp.data_keys)
  check_inputs(o.inputs or { "normal", "view" }, o.vary)
  local truth = exp.model(o.model or "phong")
  -- A Lighting value is recorded as its name and parameters (a run's config is JSON).
  local model = type(o.model) == "userdata" and { name = truth:name(), params = truth:params() } or o.model or "phong"
  local scene = self:training_scene_options(o)
  return {
    model = model,
    -- Every parameter of the ground truth as the runtime has it: a changed default is a new
    -- experiment, never a reused result.
    truth = tostring(truth),
    -- A user's model by its GLSL too (nil for a built-in): redefined under the same name, its
    -- runs' records were reused.
    truth_definition = sn.lighting.key(truth:name()),
    inputs = o.inputs or { "normal", "view" },
    vary = o.vary,                         -- nil (none) keeps older descriptions' keys
    color = o.color or "rgb",
    samples = o.samples or self:pick(8000, 64149),
    split = o.split or 0.8,
    seed = o.seed or 1,
    scene = scene,
    mesh_key = mesh_key(scene.mesh),
  }
end

-- "the cloth in 5 poses (...)" or "the hanging cloth": what --data chose, for table notes, and
-- which GGX --ggx chose when the run used GGX.
function E:data_note()
  local ggx = exp.ggx_used and "; " .. exp.ggx_notes[self.ggx_choice] or ""
  if self.data_choice == "poses" then
    return string.format("the cloth in 5 poses (upright, tilted +-60 degrees about x and about z), each from 3 rings "
                         .. "of %d views at elevations -30, 20 and 60 degrees (--data poses)", self:pick(4, 8)) .. ggx
  end
  return "the hanging cloth alone, 8 views (--data cloth, the thesis' data)" .. ggx
end

-- The scene options of training data: the mesh in the poses --data chooses (o.data overrides).
function E:training_scene_options(o)
  local so = self:scene_options(o)
  if (o.data or self.data_choice) == "poses" then
    so.poses = o.poses or exp.poses
    so.elevation = o.elevation or exp.pose_elevations
  end
  return so
end

-- E:data(options or description) -> Dataset, description. Built on first use only: a sweep
-- whose runs are all finished renders nothing.
function E:data(o)
  local d = self:data_desc(o)
  local key = json.encode(d)
  local cached = self.datasets[key]
  if cached then return cached.data, cached.desc end
  local scene = self:scene(d.scene)
  local data = self:time("dataset", function()
    return scene:dataset { inputs = d.inputs, vary = d.vary, target = exp.model(d.model), color = d.color,
                           samples = d.samples, split = d.split, seed = d.seed }
  end)
  local train, val = data:counts()
  self.datasets[key] = { data = data, desc = d }
  self.data_log = self.data_log or {}
  self.data_log[#self.data_log + 1] = { desc = d, train_rows = train, val_rows = val }
  Progress.say(string.format("%s: dataset %s -> %s: %d train / %d validation rows", self.name,
                      table.concat(d.inputs, "+"), type(d.model) == "table" and d.model.name or d.model, train, val))
  return data, d
end

-- MSE of two reference predictors on the validation rows: the training targets' mean (the best
-- constant) and all zeros (where the thesis' sigmoid and ReLU networks stalled).
function exp.baselines(data)
  local ntrain, nval = data:counts()
  local outs = data:outputs()
  local mean = {}
  for c = 1, outs do mean[c] = 0 end
  for i = 1, ntrain do
    local _, y = data:row("train", i)
    for c = 1, outs do mean[c] = mean[c] + y[c] end
  end
  for c = 1, outs do mean[c] = mean[c] / ntrain end
  local const, zeros = 0, 0
  for i = 1, nval do
    local _, y = data:row("val", i)
    for c = 1, outs do
      const = const + (y[c] - mean[c]) ^ 2
      zeros = zeros + y[c] ^ 2
    end
  end
  return { constant = const / (nval * outs), zeros = zeros / (nval * outs), mean = mean }
end

-- Baselines of the dataset `o` names, remembered for run.json.
function E:baseline(o)
  local data, d = self:data(o)
  local key = json.encode(d)
  if not self.baselines[key] then
    self.baselines[key] = exp.baselines(data)
    self.baseline_log = self.baseline_log or {}
    self.baseline_log[#self.baseline_log + 1] = { data = d, constant = self.baselines[key].constant,
                                                  zeros = self.baselines[key].zeros }
  end
  return self.baselines[key]
end

-- ---- generalisation: meshes the networks never saw -------------------------------------------

-- The unseen scenes under `light`, built once per process.
function E:unseen_scenes(light)
  local key = json.encode(light)
  self.unseen = self.unseen or {}
  if not self.unseen[key] then
    local size = self:pick({ 96, 72 }, { 160, 120 })
    local list = {}
    for _, m in ipairs(exp.unseen_meshes) do
      local mesh = type(m.mesh) == "function" and m.mesh() or m.mesh
      list[#list + 1] = { label = m.label, truths = {}, gbuffers = {},
                          scene = sn.scene { mesh = mesh, size = size, views = exp.unseen_rings, light = light } }
    end
    self.unseen[key] = list
  end
  return self.unseen[key]
end

-- Whether a network reading `inputs` can be rendered on any mesh (normal and view only; uv and
-- position mean something else on every mesh) for a ground truth `model`.
function exp.generalises(inputs, model)
  for _, a in ipairs(inputs) do
    if a ~= "normal" and a ~= "view" then return false end
  end
  return exp.model(model):name() ~= "textured_phong"
end

-- E:unseen_errors(nets, desc) -> for each network { mse, ssim, meshes = { {label, mse, ssim}, ... } },
-- or nil when the networks cannot be rendered on other meshes (exp.generalises). Image MSE over
-- covered pixels and masked SSIM of each network's render (clamped to [0, 1] as a display shows
-- it) against the ground truth, averaged over the views of each unseen mesh, then over the
-- meshes. All networks at once: sn.render_errors runs them on every thread.
function E:unseen_errors(nets, desc)
  if not exp.generalises(desc.inputs, desc.model) then return nil end
  local model = exp.model(desc.model)
  local list = self:unseen_scenes(desc.scene.light)
  local views = {}
  for _, u in ipairs(list) do
    for _, v in ipairs(exp.unseen_views) do
      local tk = desc.truth
      u.truths[tk] = u.truths[tk] or {}
      local truth = u.truths[tk][v]
      if not truth then
        truth = self:time("unseen", u.scene.render, u.scene, model, { view = v })
        u.truths[tk][v] = truth
      end
      u.gbuffers[v] = u.gbuffers[v] or u.scene:gbuffer { view = v, attributes = { "normal", "view" } }
      views[#views + 1] = { gbuffer = u.gbuffers[v], truth = truth }
    end
  end
  local errors = self:time("unseen", sn.render_errors, { nets = nets, views = views })
  local out = {}
  for i, e in ipairs(errors) do
    local o, k = { mse = 0, ssim = 0, meshes = {} }, 0
    for _, u in ipairs(list) do
      local mse, ssim = 0, 0
      for _ in ipairs(exp.unseen_views) do
        k = k + 1
        mse, ssim = mse + e[k].mse, ssim + e[k].ssim
      end
      mse, ssim = mse / #exp.unseen_views, ssim / #exp.unseen_views
      o.meshes[#o.meshes + 1] = { label = u.label, mse = mse, ssim = ssim }
      o.mse, o.ssim = o.mse + mse / #list, o.ssim + ssim / #list
    end
    out[i] = o
  end
  return out
end

-- E:unseen_error(net, desc): E:unseen_errors for one network.
function E:unseen_error(net, desc)
  local out = self:unseen_errors({ net }, desc)
  return out and out[1]
end

-- Table columns for the unseen-mesh error, and a row's values: medians over the runs `ids`.
exp.unseen_columns = {
  { key = "unseen_mse", header = "image MSE, unseen meshes", format = "%.4g" },
  { key = "unseen_ssim", header = "SSIM, unseen meshes", format = "%.4f" },
}
function exp.with_unseen(row, records, ids)
  row.unseen_mse = exp.median_of(records, ids, "unseen_mse")
  row.unseen_ssim = exp.median_of(records, ids, "unseen_ssim")
  return row
end

-- `columns` with the unseen-mesh columns inserted after the column keyed `after`.
function exp.add_unseen_columns(columns, after)
  local out = {}
  for _, c in ipairs(columns) do
    out[#out + 1] = c
    if c.key == after then
      for _, u in ipairs(exp.unseen_columns) do out[#out + 1] = u end
    end
  end
  return out
end

-- A note for tables: which meshes and views the unseen-mesh columns average over.
function exp.unseen_note()
  local names = {}
  for i, m in ipairs(exp.unseen_meshes) do names[i] = m.label end
  return string.format("Unseen meshes (no network trains on them): %s, each from 3 views at elevations -30, 20 and 60 "
                       .. "degrees; image MSE over covered pixels and SSIM (sn.image.ssim), the network's render clamped "
                       .. "to [0, 1].", table.concat(names, ", "))
end

-- ---- networks and runs ----------------------------------------------------------------------

-- "8x12", "4x6", or "13x4+6x4" for mixed widths.
function exp.arch_name(hidden)
  local parts, i = {}, 1
  while i <= #hidden do
    local j = i
    while j < #hidden and hidden[j + 1] == hidden[i] do j = j + 1 end
    parts[#parts + 1] = { w = hidden[i], n = j - i + 1 }
    i = j + 1
  end
  if #parts == 1 then return string.format("%dx%d", parts[1].n, parts[1].w) end
  local s = {}
  for k, p in ipairs(parts) do s[k] = string.format("%dx%d", p.n, p.w) end
  return table.concat(s, "+")
end

-- Weights and biases of a network: sum over layers of (in + 1) * out.
function exp.param_count(inputs, hidden, outputs)
  local n, prev = 0, inputs
  for _, w in ipairs(hidden) do
    n = n + (prev + 1) * w
    prev = w
  end
  return n + (prev + 1) * outputs
end

function exp.rep(width, count)
  local t = {}
  for i = 1, count do t[i] = width end
  return t
end

-- sn.mlp's encodings ({ uv = { "frequency", bands = 8 } }) in a form JSON holds (configs are
-- written to run.json and compared as JSON): the name under `name`; and back.
function exp.encoding_to_config(enc)
  if not enc then return nil end
  local out = {}
  for input, e in pairs(enc) do
    if type(e) == "table" then
      local c = {}
      for k, v in pairs(e) do if k ~= 1 then c[k] = v end end
      c.name = e[1]
      out[input] = c
    else
      out[input] = { name = e }
    end
  end
  return out
end
local function encoding_from_config(c)
  if not c then return nil end
  local out = {}
  for input, e in pairs(c) do
    local t = { e.name }
    for k, v in pairs(e) do if k ~= "name" then t[k] = v end end
    out[input] = t
  end
  return out
end

-- A run: { id, config }. The config holds the network, the training settings and the dataset's
-- description, so a finished run is reused only for exactly the same experiment.
-- o = { id, hidden, data (desc), seed, epochs, batch, adam, outputs, activation, slope, omega, alpha,
--       output_activation, init, encoding (sn.mlp's, by input name), keep_params, tag, backend,
--       alone, copies } (docs/lua-api/experiments.md says what each does)
exp.run_keys = { "id", "hidden", "data", "seed", "epochs", "batch", "adam", "outputs", "activation", "slope", "omega",
                 "alpha", "output_activation", "init", "encoding", "keep_params", "tag", "backend", "alone", "copies" }
function exp.run(o)
  options.check(o, "exp.run", exp.run_keys, { "id", "hidden", "data", "seed" },
                { id = "the run's name", hidden = "the hidden layers' widths", data = "a dataset description: E:data_desc{...}",
                  seed = "its initial weights' and its shuffle's seed" })
  if type(o.data) ~= "table" or not o.data.scene then
    options.error("exp.run option 'data' is " .. (type(o.data) == "table" and "not a dataset description" or "a " .. type(o.data))
                  .. " (give E:data_desc{...}'s result)")
  end
  local adam = o.adam or exp.adam
  -- The keys of a user's activations and encodings (their GLSL; nil for built-ins): redefined
  -- under the same names, their runs' records were reused. (A name sn.mlp will refuse is left to it.)
  local definitions = {}
  local function note(kind, name)
    local ok, key = pcall(sn[kind].key, name)
    if ok and key then definitions[kind .. " " .. name] = key end
  end
  note("activation", o.activation or "tanh")
  if o.output_activation then note("activation", o.output_activation) end
  for _, e in pairs(o.encoding or {}) do note("encoding", type(e) == "table" and e[1] or e) end
  return {
    id = o.id,
    config = {
      hidden = o.hidden,
      outputs = o.outputs or 3,
      activation = o.activation or "tanh",
      slope = o.slope,
      omega = o.omega,                       -- nil (the defaults) keeps older configs' keys
      alpha = o.alpha,
      output_activation = o.output_activation,
      encoding = exp.encoding_to_config(o.encoding),  -- nil (none) keeps older configs' keys
      init = o.init,
      color = o.data.color,
      seed = o.seed,
      epochs = o.epochs or exp.epochs,
      batch = o.batch or exp.batch,
      adam = { lr = adam.lr, beta1 = adam.beta1, beta2 = adam.beta2 },
      data = o.data,
      keep_params = o.keep_params or nil,
      tag = o.tag,
      backend = o.backend,               -- nil: the script's --backend
      job = o.alone and o.id or nil,     -- alone: trained in a job of its own (for timings)
      copies = o.copies,                 -- train this many networks (seeds seed, seed+1, ...) in its job
      definitions = next(definitions) and definitions or nil,  -- nil (built-ins only) keeps older configs' keys
    },
  }
end

-- A fresh network for a run's config (its seed picks the initial weights). Its inputs by name:
-- sn.mlp takes their widths from the runtime's attributes (a varied parameter is one column).
function exp.make_net(c)
  return sn.mlp { inputs = c.data.inputs, hidden = c.hidden, outputs = c.outputs,
                  activation = c.activation, slope = c.slope, omega = c.omega, alpha = c.alpha,
                  output_activation = c.output_activation, init = c.init, color = c.color, seed = c.seed,
                  encoding = encoding_from_config(c.encoding) }
end

-- The trained network of a finished record (needs keep_params in its config). `id` names the
-- run in the error when there is no record: under --shard i/n every sweep is split, so a
-- figure's one-run sweep trains in one shard only (the first) and the others have no record.
function exp.net_from_record(rec, id)
  if not rec then
    error(string.format("exp.net_from_record: run %s is not finished in this folder: under --shard i/n every "
                        .. "E:sweep is split round robin, so a sweep of one run trains in shard 1 only; check "
                        .. "`if records[id]`, or draw the figure after merging the shards (scripts/merge.lua)",
                        id and ("'" .. tostring(id) .. "'") or "(nil record)"), 2)
  end
  assert(rec.result.params, "run " .. rec.id .. " kept no parameters (keep_params)")
  local net = exp.make_net(rec.config)
  net:set_params(rec.result.params)
  return net
end

-- Validation MSE in RGB of a network that outputs another colour space: its outputs on the
-- validation rows of `rgb_data` (a dataset with the same rows and RGB targets) decoded to RGB.
-- The forward pass runs in a compute shader; only the decoding is a Lua loop.
function exp.rgb_val_mse(net, rgb_data)
  local space = net:spec().color
  local out = net:forward(rgb_data, "val")
  sn.finish()
  local p = out:ffi()
  local _, nval = rgb_data:counts()
  local k = net:spec().outputs
  assert(out:size() == nval * k, "net:forward returned " .. out:size() .. " numbers for " .. nval .. " rows")
  local sum = 0
  for i = 1, nval do
    local o = { p[(i - 1) * k], p[(i - 1) * k + 1], p[(i - 1) * k + 2] }
    local rgb = space == "rgb" and o or sn.color.decode(space, o)
    local _, y = rgb_data:row("val", i)
    for c = 1, 3 do sum = sum + (rgb[c] - y[c]) ^ 2 end
  end
  out:release()
  return sum / (3 * nval)
end

-- Rendering cost of a network over a G-buffer: seconds per frame drawn, and seconds of one
-- whole call (draw and read-back). net:render's `frames` draws that many frames before reading
-- the image back, so a call of 1 + n frames less a call of 1 frame is n frames of drawing
-- alone; n doubles from `frames` until those n frames take at least `min_seconds`, so the
-- difference stands well above the noise of a shared machine; the long call is timed twice and
-- the faster kept (another process only ever adds time). A warm-up call first compiles the
-- shader and uploads the weights.
function exp.render_seconds(net, g, frames, min_seconds)
  min_seconds = min_seconds or 0.05
  local function call(n)
    local t0 = sn.clock()
    net:render(g, { frames = n })
    sn.finish()
    return sn.clock() - t0
  end
  call(1)
  local one = { call(1), call(1), call(1) }
  table.sort(one)
  local n = frames
  while true do
    local drawing = math.min(call(n + 1), call(n + 1)) - one[2]
    if drawing >= min_seconds or n >= 65536 then return math.max(drawing, 0) / n, one[2] end
    n = n * 2
  end
end

-- Runs that may train in one job: same data, epochs, batch and Adam settings. Each run's seed
-- is its nets' shuffle seed (sn.train's seed per net), so a run's result never depends on which
-- runs it shared a job with: shards and resumed sweeps give exactly the unsharded numbers, and
-- a sweep's seeds train together (the cpu backend pairs nets of one architecture across them).
function exp.group_key(run)
  local c = run.config
  return json.encode { c.data, c.epochs, c.batch, c.adam, c.backend or "", c.job or "" }
end

-- Trains one group; returns one result table per run. tick(fraction) hears how far it is.
function E:train_group(group, tick)
  local c = group[1].config
  local data = self:data(c.data)
  local nets, first, seeds = {}, {}, {}
  for i, r in ipairs(group) do
    first[i] = #nets + 1
    for k = 1, r.config.copies or 1 do
      local cfg = r.config
      if k > 1 then
        cfg = setmetatable({ seed = r.config.seed + k - 1 }, { __index = r.config })
      end
      nets[#nets + 1] = exp.make_net(cfg)
      seeds[#nets] = r.config.seed  -- copies differ in their start, not in their shuffle
    end
  end
  local epochs_done, total = 0, #nets * c.epochs
  local out = self:time("training", sn.train, {
    nets = nets, data = data, epochs = c.epochs, batch = c.batch, adam = c.adam, seed = seeds,
    backend = c.backend or self.backend, keep = "best",
    progress = tick and function()
      epochs_done = epochs_done + 1
      tick(epochs_done / total)
    end or nil,
  })
  -- Ctrl-C stopped sn.train: a run any of whose copies stopped part-way is not a result (the
  -- sweep leaves it for the next run of the command).
  local stopped, scored = {}, {}
  for i, r in ipairs(group) do
    for k = first[i], first[i] + (r.config.copies or 1) - 1 do stopped[i] = stopped[i] or out[k].interrupted end
    if not stopped[i] and stats.finite(out[first[i]].best_val_mse) then scored[#scored + 1] = i end
  end
  local scored_nets, unseen_of = {}, {}
  for j, i in ipairs(scored) do scored_nets[j] = nets[first[i]] end
  local errors = #scored_nets > 0 and self:unseen_errors(scored_nets, c.data) or {}
  for j, i in ipairs(scored) do unseen_of[i] = errors[j] end
  local res = {}
  for i, r in ipairs(group) do
    local o = out[first[i]]
    local stopped = stopped[i]
    local p = nil
    if r.config.keep_params then p = nets[first[i]]:params() end
    local unseen = unseen_of[i]
    res[i] = {
      unseen_mse = unseen and unseen.mse, unseen_ssim = unseen and unseen.ssim,
      best_val_mse = o.best_val_mse, best_epoch = o.best_epoch,
      val_mse = o.val_mse, train_mse = o.train_mse,
      wall_time = o.wall_time, job_nets = #nets, steps = o.steps, sample_steps_per_s = o.sample_steps_per_s,
      diverged = o.diverged, dead_units = o.dead_units, stuck_outputs = o.stuck_outputs, backend = o.backend,
      device = o.device,
      params = p, interrupted = stopped,
    }
    if not stopped and not stats.finite(o.best_val_mse) then
      io.stderr:write(string.format("%s: run %s has no finite validation MSE (diverged at epoch %s)\n", self.name,
                                    r.id, o.diverged and tostring(o.diverged.epoch) or "?"))
    end
  end
  return res
end

-- E:sweep(runs [, { chunk = N, label }]) -> records by id (every finished run found, this shard's
-- and any merged in), interrupted
function E:sweep(runs, o)
  o = options.check(o or {}, "E:sweep", { "chunk", "label" })
  -- A finished run is reused when it was trained on the backend asked for: --backend auto (the
  -- default) takes any; --backend cpu or gl trains again the runs another backend trained.
  local function wanted(run) return run.config.backend or self.backend end
  local sweep = Sweep.new { dir = self.dir, runs = runs, shard = self.opts.shard, label = o.label or self.name,
                            accept = function(rec, run)
                              local want, got = wanted(run), type(rec.result) == "table" and rec.result.backend
                              return want == "auto" or not got or got == want
                            end }
  -- The folder's claim: these runs are the ones its flags make (lib.claim).
  local key = claim.runs_key(runs)
  self.claim:check_sweep(#self.sweeps + 1, key)
  if self.interrupted and not exp.report_only then
    -- Ctrl-C or SIGTERM stopped an earlier sweep: this one does not start (its runs count as not
    -- run; the tables' "Partial results" notice says so), and the script ends soon with 130 or 143.
    local by_id, finished = {}, 0
    for _, rec in ipairs(sweep:records()) do by_id[rec.id] = rec end
    for _, r in ipairs(sweep:slice()) do if by_id[r.id] then finished = finished + 1 end end
    print(string.format("%s: not started (stopped by Ctrl-C or SIGTERM); %d of %d runs already finished in %s/runs",
                        o.label or self.name, finished, #sweep:slice(), self.dir))
    self.sweeps[#self.sweeps + 1] = { runs = #runs, slice = #sweep:slice(), finished = finished, interrupted = true,
                                      not_started = true, key = key }
    self:note_partial()
    self:note_used(by_id)
    return by_id, true
  end
  local refused = {}
  for _, r in ipairs(sweep:slice()) do
    local rec = not sweep:record(r) and sweep:record(r, true)
    if rec then
      local k = rec.result.backend .. " -> " .. wanted(r)
      refused[k] = (refused[k] or 0) + 1
    end
  end
  for k, n in pairs(refused) do
    local got, want = k:match("^(.-) %-> (.*)$")
    io.stderr:write(string.format("%s: %d finished runs in %s/runs were trained on the %s backend; --backend %s %s\n",
                                  self.name, n, self.dir, got, want,
                                  exp.report_only and "leaves them out (merge: the shards asked for different backends?)"
                                    or "trains them again (--backend auto reuses them)"))
  end
  if exp.report_only then
    -- scripts/merge.lua: report what the shards ran, train nothing.
    local pending = sweep:pending()
    local missing, other = #pending, 0
    for _, r in ipairs(pending) do
      if sn.fs.exists(sweep:file(r)) then other = other + 1 end
    end
    if missing > 0 then
      local ids = {}
      for i = 1, math.min(#pending, 8) do ids[i] = pending[i].id end
      io.stderr:write(string.format("%s: %d of %d runs are not among the merged run files (%s%s%s); a cell is the "
                                    .. "median of the runs there, – where there are none\n",
                                    self.name, missing, #runs, table.concat(ids, ", "), #pending > 8 and ", ..." or "",
                                    other > 0 and string.format("; %d of them are there with another configuration: "
                                                                .. "run with other options, by another version of "
                                                                .. "the script, or unreadable", other)
                                      or "; a shard that is missing, unfinished or stopped?"))
      -- Every table says so at its top (it looked complete, its cells medians of fewer seeds).
      self.R.partial = string.format("**Partial results (merged):** %d of %d runs are not among the merged shards' "
                                     .. "run files; a cell is the median of the runs there, – where there are none. "
                                     .. "Merge again with every shard finished.", missing, #runs)
      self.partial_title = "partial: runs missing from the merge, see table.md"
    end
    local by_id = {}
    for _, rec in ipairs(sweep:records()) do by_id[rec.id] = rec end
    self:note_used(by_id)
    self.sweeps[#self.sweeps + 1] = { runs = #runs, finished = #runs - missing, merged = true, key = key }
    return by_id, false
  end
  local finished, interrupted = sweep:run {
    train = function(group, tick) return self:train_group(group, tick) end,
    group_key = exp.group_key,
    chunk = self.opts.runs_per_job or o.chunk,
    score = function(r) return r.best_val_mse end,
    describe = function(run) return exp.arch_name(run.config.hidden) .. " seed " .. run.config.seed end,
  }
  self.sweeps[#self.sweeps + 1] = { runs = #runs, slice = #sweep:slice(), finished = finished, interrupted = interrupted,
                                    key = key }
  if interrupted and not self.interrupted then
    self.interrupted = true
    local _, signal = sn.interrupted()
    self.signal = signal or 2  -- (sn.train's own Ctrl-C catch: SIGINT)
  end
  if interrupted then self:note_partial() end
  local by_id = {}
  for _, rec in ipairs(sweep:records()) do by_id[rec.id] = rec end
  self:note_used(by_id)
  return by_id, interrupted
end

-- After Ctrl-C or SIGTERM: every table written from here on says at its top that its results are
-- partial, counting the runs of every sweep so far (those that did not start among them).
function E:note_partial()
  local finished, total, skipped, skipped_runs = 0, 0, 0, 0
  for _, s in ipairs(self.sweeps) do
    finished, total = finished + (s.finished or 0), total + (s.slice or s.runs)
    if s.not_started then skipped, skipped_runs = skipped + 1, skipped_runs + (s.slice or s.runs) end
  end
  self.R.partial = string.format("**Partial results:** the sweep was stopped (Ctrl-C or SIGTERM) with %d of %d "
                                 .. "runs finished%s; – marks the others. Run the same command to resume.", finished,
                                 total, skipped > 0 and string.format(" (%d later sweep%s of %d runs not started)",
                                                                      skipped, skipped > 1 and "s" or "", skipped_runs)
                                                      or "")
  self.partial_title = "partial: the sweep was stopped, see table.md"
end

-- Remembers the backends and devices of the records a sweep returned, for run.json.
function E:note_used(by_id)
  self.used = self.used or { backend = {}, device = {}, build = {}, ids = {} }
  for id, rec in pairs(by_id) do
    if self.used.ids[id] then goto next end
    self.used.ids[id] = true
    for _, k in ipairs { "backend", "device" } do
      local v = tostring(rec.result[k] or "unknown")
      self.used[k][v] = (self.used[k][v] or 0) + 1
    end
    -- The build that trained it (lib.sweep records it; "unknown" for records from before).
    local b = type(rec.build) == "string" and rec.build or "unknown"
    self.used.build[b] = (self.used.build[b] or 0) + 1
    ::next::
  end
end

-- "cpu", or "cpu, gl" when the records were trained on both; nil with no record.
local function used_text(counts, sep)
  local names = {}
  for k in pairs(counts or {}) do names[#names + 1] = k end
  table.sort(names)
  return #names > 0 and table.concat(names, sep) or nil
end

-- Median of `field` over the records of `ids`; also the number of runs found and of those
-- without a finite value (diverged). A run that diverged before its first validation has no
-- value at all (nil): it counts as diverged too, never as a run that is not there.
function exp.median_of(records, ids, field)
  local vals, found = {}, 0
  for _, id in ipairs(ids) do
    local rec = records[id]
    if rec then
      found = found + 1
      local v = rec.result[field]
      vals[#vals + 1] = v == nil and 0 / 0 or v
    end
  end
  local m, bad = stats.median(vals)
  return m, found, bad or 0
end

-- Dead units per hidden layer (the fraction of its units), the mean over the records of `ids`
-- that are there and hold them: a shard's or a stopped sweep's table has fewer than all seeds.
function exp.dead_units_per_layer(records, ids)
  local per_layer, n = {}, 0
  for _, id in ipairs(ids) do
    local rec = records[id]
    if rec and type(rec.result.dead_units) == "table" then
      n = n + 1
      for l, f in ipairs(rec.result.dead_units) do per_layer[l] = (per_layer[l] or 0) + f end
    end
  end
  for l in ipairs(per_layer) do per_layer[l] = per_layer[l] / n end
  return per_layer
end

-- ---- outputs --------------------------------------------------------------------------------

-- E:plot("plots/NAME.png", spec for lib.plot.lines) -> path; the CSV lands beside it.
function E:plot(rel, p)
  options.check(p, "E:plot", plot.keys)
  p.path = self.R:path(rel)
  p.title = self:marked_title(p.title)
  local path, dropped = plot.lines(p)
  local w = self.R.written
  w[#w + 1] = path:match("%.gp$") and (rel:gsub("%.png$", ".gp")) or rel  -- SHADENET_PLOTS=later: the script
  w[#w + 1] = (rel:gsub("%.png$", ".csv"))
  if dropped > 0 then
    io.stderr:write(string.format("%s: %s: %d non-finite points left out of the plot\n", self.name, rel, dropped))
  end
  return path
end

-- A figure's or plot's title, marked when the results are partial (a stopped sweep, a merge with
-- runs missing): a figure with 2 of its 4 networks looked whole beside a table that said otherwise.
function E:marked_title(title)
  if not self.partial_title then return title end
  return (title and title ~= "" and title .. " " or "") .. "(" .. self.partial_title .. ")"
end

-- E:figure("figures/NAME.png", image) -> path (written atomically).
function E:figure(rel, img)
  img:save(self.R:path(rel))
  self.R.written[#self.R.written + 1] = rel
  return self.R:path(rel)
end

-- ---- image grids: truth | networks, with error heatmaps under them ---------------------------

local function blank() return sn.image.new { width = 1, height = 1, channels = 3, fill = 1 } end

-- How much a network's render differs in colour from its ground truth where the truth covers:
-- the mean over those pixels of |c(network) - c(truth)|, c = max(RGB) - min(RGB) (0 for a grey):
-- the colour shifts the thesis saw in over-wide networks (figs. 4.2, 4.12).
exp.colour_shift_note = "Colour shift: the mean over the covered pixels of the training mesh of |c(network) - c(truth)|, "
  .. "c = max(RGB) - min(RGB) of a pixel (0 for a grey): colour the network adds or loses."
function exp.colour_shift(img, truth)
  local w, h = img:size()
  local sum, n = 0, 0
  local function c(p) return math.max(p[1], p[2], p[3]) - math.min(p[1], p[2], p[3]) end
  for y = 1, h do
    for x = 1, w do
      local t = truth:get(x, y)
      if t[4] > 0 then
        sum = sum + math.abs(c(img:get(x, y)) - c(t))
        n = n + 1
      end
    end
  end
  return n > 0 and sum / n or 0
end

function exp.frame(img, margin)
  local x, y, w, h = sn.image.covered_box(img)
  local iw, ih = img:size()
  if not x then return { 1, 1, iw, ih } end
  local mx, my = math.ceil(w * (margin or 0.05)), math.ceil(h * (margin or 0.05))
  local x0, y0 = math.max(1, x - mx), math.max(1, y - my)
  local x1, y1 = math.min(iw, x + w - 1 + mx), math.min(ih, y + h - 1 + my)
  return { x0, y0, x1 - x0 + 1, y1 - y0 + 1 }
end

function exp.crop(img, box) return sn.image.crop(img, box[1], box[2], box[3], box[4]) end

-- E:compare's nets and meshes: each entry named ({ net = Mlp, label = "8x12" }) or its values in
-- the order of `keys` ({ Mlp, "8x12" }, as the docs first showed them), as named tables.
local function entries(list, what, keys, required)
  if type(list) ~= "table" then options.error(string.format("%s: a list expected, got %s", what, type(list))) end
  local out = {}
  for i, e in ipairs(list) do
    local at = string.format("%s[%d]", what, i)
    if type(e) ~= "table" then
      options.error(string.format("%s: { %s } expected, got %s", at, table.concat(keys, ", "), type(e)))
    end
    local named = {}
    for k, v in pairs(e) do
      if type(k) == "number" then
        if not keys[k] then
          options.error(string.format("%s: at most %d values in order (%s), got one at [%s]", at, #keys,
                                      table.concat(keys, ", "), tostring(k)))
        end
        if e[keys[k]] ~= nil then
          options.error(string.format("%s: '%s' given twice, as [%d] and by name", at, keys[k], k))
        end
        named[keys[k]] = v
      else
        named[k] = v
      end
    end
    out[i] = options.check(named, at, keys, required)
  end
  return out
end

-- E:compare{ file = "figures/NAME.png", title = "...", model = "ggx" (the ground truth),
--            nets = { {net = Mlp, label = "8x12"}, ... } (or { {Mlp, "8x12"}, ... }),
--            meshes = { {mesh = path, label = "training mesh", views = {1, 3}, view_count = 8}, ... }
--              (or { {path, "training mesh", {1, 3}, 8}, ... }),
--            size = {w, h}, view_count = 8, max = error at the top of the colour bar (default: the
--            largest error on that mesh, shared by every heatmap of the mesh so they compare),
--            colour_shift = true (each row also gets exp.colour_shift(network, truth)) }
-- One pair of rows per (mesh, view): the truth and each network's rendering, captioned with its
-- MSE over the covered pixels, then the |error| heatmaps under them. Network renders are
-- clamped to [0, 1] as a display shows them (the truth is). Writes the PNG and a CSV of the
-- MSEs beside it; returns the MSE rows.
exp.compare_keys = { "file", "title", "model", "nets", "meshes", "size", "view_count", "max", "colour_shift" }
function E:compare(o)
  options.check(o, "E:compare", exp.compare_keys, { "file", "model", "nets", "meshes" })
  o = setmetatable({ nets = entries(o.nets, "E:compare nets", { "net", "label" }, { "net", "label" }),
                     meshes = entries(o.meshes, "E:compare meshes", { "mesh", "label", "views", "view_count" },
                                      { "mesh", "label" }) }, { __index = o })
  local truth_model = exp.model(o.model)
  local size = o.size or self:pick({ 200, 150 }, { 480, 360 })
  local renders, rows = {}, {}
  local max_err = {}
  for _, m in ipairs(o.meshes) do
    local scene = self:scene { mesh = m.mesh, size = size, views = m.view_count or o.view_count or 8 }
    for _, v in ipairs(m.views or { 1 }) do
      local full_truth = self:time("render", scene.render, scene, truth_model, { view = v })
      local box = exp.frame(full_truth)
      local truth = exp.crop(full_truth, box)
      local entry = { label = string.format("%s, view %d", m.label, v), truth = truth, nets = {} }
      for k, n in ipairs(o.nets) do
        local img = sn.image.clamp(exp.crop(self:time("render", scene.render, scene, n.net, { view = v }), box))
        local mse = sn.image.mse(truth, img, { channels = 3, mask = truth })
        local diff = sn.image.diff(truth, img)
        local _, mx, bad = sn.image.heatmap(diff, { mask = truth, colorbar = false })
        max_err[m.label] = math.max(max_err[m.label] or 0, mx)
        if bad > 0 then
          io.stderr:write(string.format("%s: %s renders %d NaN/Inf pixels on the %s, view %d (magenta in %s)\n",
                                        self.name, n.label, bad, m.label, v, o.file))
        end
        entry.nets[k] = { img = img, diff = diff, mse = mse }
        rows[#rows + 1] = { mesh = m.label, view = v, network = n.label, mse = mse, non_finite_pixels = bad,
                            colour_shift = o.colour_shift and exp.colour_shift(img, truth) or nil }
      end
      entry.mesh = m.label
      renders[#renders + 1] = entry
    end
  end
  local panels, row_labels = {}, {}
  if #o.nets == 1 then
    -- One network: truth | network | error side by side, a row per view.
    for _, e in ipairs(renders) do
      local n = e.nets[1]
      panels[#panels + 1] = { image = e.truth, caption = "ground truth" }
      panels[#panels + 1] = { image = n.img, caption = string.format("%s  MSE %.2e", o.nets[1].label, n.mse) }
      panels[#panels + 1] = { image = sn.image.heatmap(n.diff, { mask = e.truth, max = o.max or max_err[e.mesh],
                                                                label = "|error|" }), caption = "error" }
      row_labels[#row_labels + 1] = e.label
    end
  else
    -- Several: a row of renders, the row of their errors under it.
    for _, e in ipairs(renders) do
      panels[#panels + 1] = { image = e.truth, caption = "ground truth" }
      for k, n in ipairs(e.nets) do
        panels[#panels + 1] = { image = n.img, caption = string.format("%s  MSE %.2e", o.nets[k].label, n.mse) }
      end
      row_labels[#row_labels + 1] = e.label
      panels[#panels + 1] = { image = blank(), caption = "" }
      for _, n in ipairs(e.nets) do
        local h = sn.image.heatmap(n.diff, { mask = e.truth, max = o.max or max_err[e.mesh], label = "|error|" })
        panels[#panels + 1] = { image = h, caption = "" }
      end
      row_labels[#row_labels + 1] = "error"
    end
  end
  local img = sn.image.grid { panels = panels, columns = #o.nets == 1 and 3 or #o.nets + 1, row_labels = row_labels,
                              title = self:marked_title(o.title), caption_size = size[1] >= 300 and 14 or 11 }
  self:figure(o.file, img)
  local csv = o.file:gsub("%.png$", ".csv")
  local columns = { { key = "mesh" }, { key = "view" }, { key = "network" }, { key = "mse" }, { key = "non_finite_pixels" } }
  if o.colour_shift then columns[#columns + 1] = { key = "colour_shift" } end
  if self.partial_title then  -- the CSV says so too, on every row
    columns[#columns + 1] = { key = "partial" }
    for _, r in ipairs(rows) do r.partial = self.partial_title end
  end
  self.R:write(csv, results.csv(columns, rows))
  return rows
end

-- How our cells compare with the thesis': Spearman's rank correlation (ties get average ranks)
-- and the median of ours / thesis over the rows that have both `key` and `thesis_key`;
-- `notes` are the lines a table prints at its bottom (nil where a number has too few cells).
function exp.vs_thesis(rows, key, thesis_key)
  local idx = {}
  for i, r in ipairs(rows) do
    if stats.finite(r[key]) and stats.finite(r[thesis_key]) then idx[#idx + 1] = i end
  end
  -- Ranks 1..n; tied values share the mean of their positions (the thesis prints values to 2-3
  -- digits, so its tables have ties), and the row index breaks no tie.
  local function ranks(k)
    local order = { unpack(idx) }
    table.sort(order, function(a, b) return rows[a][k] < rows[b][k] or (rows[a][k] == rows[b][k] and a < b) end)
    local rk, pos = {}, 1
    while pos <= #order do
      local last = pos
      while last < #order and rows[order[last + 1]][k] == rows[order[pos]][k] do last = last + 1 end
      for j = pos, last do rk[order[j]] = (pos + last) / 2 end
      pos = last + 1
    end
    return rk
  end
  local n = #idx
  local ro, rt = ranks(key), ranks(thesis_key)
  local ratios = {}
  for _, i in ipairs(idx) do ratios[#ratios + 1] = rows[i][key] / rows[i][thesis_key] end
  -- Spearman's rho: Pearson's correlation of the ranks (1 - 6 sum d^2 / (n (n^2 - 1)) only holds
  -- without ties). nil when either side is all one value.
  local spearman
  if n > 2 then
    local mean = (n + 1) / 2
    local so, st, sot = 0, 0, 0
    for _, i in ipairs(idx) do
      so, st, sot = so + (ro[i] - mean) ^ 2, st + (rt[i] - mean) ^ 2, sot + (ro[i] - mean) * (rt[i] - mean)
    end
    if so > 0 and st > 0 then spearman = sot / math.sqrt(so * st) end
  end
  local median_ratio = stats.median(ratios)
  return {
    n = n, spearman = spearman, median_ratio = median_ratio,
    notes = {
      spearman and string.format("Rank correlation (Spearman) of our cells with the thesis' over the %d cells: %.3f.", n,
                                 spearman) or nil,
      median_ratio and string.format("Median over the cells of ours / thesis: %.3g.", median_ratio) or nil,
    },
  }
end

-- ---- finish ---------------------------------------------------------------------------------

-- E:finish{ config = {...}, summary = {...} }: writes run.json and prints where everything is.
-- When Ctrl-C or SIGTERM stopped a sweep, the partial results are written and the process exits
-- with 130 or 143.
function E:finish(o)
  o = options.check(o or {}, "E:finish", { "records", "config", "summary" })
  local total = sn.clock() - self.t0
  self.timings.total = total
  -- The backends and devices of every record the tables used (all of them when they differ,
  -- with how many runs each trained); `o.records` for records a script found another way.
  if o.records then self:note_used(o.records) end
  local used = self.used or {}
  local backend_used, device = used_text(used.backend, ", "), used_text(used.device, "; ")
  -- Runs from other builds than this one (a resumed sweep, merged shards): said, and run.json
  -- lists every build with its runs (environment.build is this binary's).
  local builds = used_text(used.build, ", ")
  if builds and builds ~= sn.build then
    local parts = {}
    for b, n in pairs(used.build) do parts[#parts + 1] = string.format("%s: %d", b, n) end
    table.sort(parts)
    io.stderr:write(string.format("%s: the tables' runs were trained by %s (%s; this binary is %s): numbers of "
                                  .. "different builds may differ; run.json lists them (runs_per_build)\n", self.name,
                                  #parts > 1 and #parts .. " builds" or "another build", table.concat(parts, ", "),
                                  sn.build))
  end
  local env = results.environment()
  local info = {
    experiment = self.name,
    command = "shadenet " .. self.script .. " " .. table.concat(self.args, " "),
    script = self.script,
    quick = self.quick,
    -- what chose the data (scripts/merge.lua re-runs the experiment with them)
    options = { data = self.data_choice, ggx = self.ggx_choice },
    flags = next(self.own_flags) and self.own_flags or nil,  -- the script's own (exp.start's flags), as given
    flag_values = next(self.own_flags) and claim.flag_values(self.own_flags) or nil,  -- as lib.claim compares them
    shard = self.opts.shard,
    backend = { requested = self.backend, used = backend_used, device = device, runs_per_backend = used.backend,
                runs_per_device = used.device },
    builds = builds,  -- the builds that trained the tables' runs ("a, b" when several)
    runs_per_build = used.build,
    environment = env,
    datasets = self.data_log,
    baselines = self.baseline_log,
    config = o.config,
    summary = o.summary,
    sweeps = self.sweeps,
    timings = self.timings,
    load_average = { at_start = self.load_at_start, at_end = results.load_average() },
    interrupted = self.interrupted or nil,
    files = self.R.written,
  }
  self.R:json("run.json", info)
  print(string.format("%s: done in %.1f s; wrote %s/{%s}", self.name, total, self.dir,
                      table.concat(self.R.written, ",")))
  if self.interrupted then
    os.exit(128 + (self.signal or 2))  -- 130 after Ctrl-C, 143 after SIGTERM, as the shell reports a killed process
  end
  return info
end

return exp
